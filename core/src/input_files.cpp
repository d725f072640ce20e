#include "igaprep/core/input_files.h"

#include <filesystem>
#include <system_error>

#include "igaprep/core/error.h"

namespace igaprep {

void require_regular_file(const std::string& path, const std::string& what) {
  std::error_code ec;
  const std::filesystem::file_status st = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(st))
    throw bad_input(path + ": cannot open the " + what + " (missing or not readable)");
  if (std::filesystem::is_directory(st)) throw bad_input(path + ": is a folder, not a " + what);
  if (!std::filesystem::is_regular_file(st))
    throw bad_input(path + ": is not a regular file (a FIFO, a device or a socket), not a " + what);
}

void refuse_replacing_inputs(const std::vector<std::string>& inputs, const std::vector<std::string>& outputs) {
  for (const std::string& out : outputs)
    for (const std::string& in : inputs) {
      std::error_code ec;  // a missing file is no match
      if (std::filesystem::equivalent(in, out, ec))
        throw bad_input("output '" + out + "' is the input '" + in +
                        "' (the same file): it would be replaced; choose another output");
    }
}

}  // namespace igaprep
