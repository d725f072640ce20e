// libFuzzer target: mesh::read_surface on arbitrary bytes, saved under the
// extension FUZZ_EXTENSION (".stl", ".obj", ".off", ".ply": the format is
// detected from the content, the extension breaks ties). Every input must
// end in a TriMesh or an igaprep::Error; anything else (a crash, a
// sanitizer report, another exception) is a finding. Built by scripts/fuzz.sh.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "igaprep/core/error.h"
#include "igaprep/mesh/read_surface.h"

#ifndef FUZZ_EXTENSION
#error "FUZZ_EXTENSION must name the file extension, e.g. \".stl\""
#endif

namespace {

// One file per process, rewritten for each input (in memory: /dev/shm).
const std::string& input_path() {
  static const std::string path = "/dev/shm/igaprep-fuzz-" + std::to_string(::getpid()) + FUZZ_EXTENSION;
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = input_path();
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  try {
    const igaprep::mesh::TriMesh mesh = igaprep::mesh::read_surface(path);
    // Whatever was read must index its own vertices.
    for (Eigen::Index i = 0; i < mesh.F.size(); ++i)
      if (mesh.F.data()[i] < 0 || mesh.F.data()[i] >= mesh.V.rows()) __builtin_trap();
  } catch (const igaprep::Error& e) {
    if (e.kind() == igaprep::ErrorKind::Internal) __builtin_trap();
  }
  return 0;
}
