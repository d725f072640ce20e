#include "igaprep/core/file_identity.h"

#include <filesystem>
#include <system_error>

#include "igaprep/core/error.h"

namespace igaprep {

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
