#pragma once
// The one exception type of igaprep (ARCHITECTURE.md, "Errors"): a category
// that decides the CLI's exit code, and a message that names what is at fault.
#include <stdexcept>
#include <string>

namespace igaprep {

enum class ErrorKind {
  BadInput = 1,     // bad input file, parameter or usage: exit code 1
  CheckFailed = 2,  // a check found the model unfit (e.g. negative Jacobian): exit code 2
  Internal = 3,     // a failure of igaprep or of a library it calls: exit code 3
};

class Error : public std::runtime_error {
 public:
  Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  ErrorKind kind() const { return kind_; }
  int exit_code() const { return static_cast<int>(kind_); }

 private:
  ErrorKind kind_;
};

// Shorthands that read well at the throw site.
inline Error bad_input(const std::string& message) { return Error(ErrorKind::BadInput, message); }
inline Error check_failed(const std::string& message) { return Error(ErrorKind::CheckFailed, message); }
inline Error internal_error(const std::string& message) { return Error(ErrorKind::Internal, message); }

}  // namespace igaprep
