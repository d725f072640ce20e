// libFuzzer target: pipeline::parse_case on arbitrary JSON text. Every input
// must end in a Case or an igaprep::Error of kind BadInput; anything else (a
// crash, a sanitizer report, an internal error, another exception) is a
// finding. Built by scripts/fuzz.sh.
#include <cstddef>
#include <cstdint>
#include <string>

#include "igaprep/core/error.h"
#include "igaprep/pipeline/case.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const igaprep::pipeline::Case c = igaprep::pipeline::parse_case(text, "/nonexistent-fuzz-folder", "fuzz.json");
    (void)c;
  } catch (const igaprep::Error& e) {
    if (e.kind() == igaprep::ErrorKind::Internal) __builtin_trap();
  }
  return 0;
}
