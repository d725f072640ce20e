#include "igaprep/core/input_files.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
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

std::string read_input_file(const std::string& path, const std::string& what) {
  require_regular_file(path, what);
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw bad_input(path + ": cannot open the " + what + ": " + std::strerror(errno));
  std::string data;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n > 0) {
      data.append(buffer, static_cast<std::size_t>(n));
    } else if (n == 0) {
      break;
    } else if (errno != EINTR) {
      const int error = errno;
      ::close(fd);
      throw bad_input(path + ": read error after " + std::to_string(data.size()) + " bytes of the " + what + ": " +
                      std::strerror(error));
    }
  }
  ::close(fd);
  return data;
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
