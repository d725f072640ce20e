// The fuzzers' inputs replayed through the surface reader (scripts/fuzz.sh):
// the seed corpus and every input a fuzzer once crashed on
// (fuzz/regressions/<format>/), each read or refused as bad input.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "igaprep/core/error.h"
#include "igaprep/mesh/read_surface.h"

namespace {

namespace fs = std::filesystem;

// The fuzzer writes its input under the format's extension; so does this.
int replay(const fs::path& folder, const std::string& extension, const fs::path& scratch) {
  int replayed = 0;
  if (!fs::is_directory(folder)) return 0;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const fs::path input = scratch / ("input" + extension);
    fs::copy_file(entry.path(), input, fs::copy_options::overwrite_existing);
    try {
      const igaprep::mesh::TriMesh m = igaprep::mesh::read_surface(input.string());
      EXPECT_GT(m.F.rows(), 0) << entry.path();
      EXPECT_TRUE(m.F.size() == 0 || (m.F.minCoeff() >= 0 && m.F.maxCoeff() < m.V.rows())) << entry.path();
    } catch (const igaprep::Error& e) {
      EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput) << entry.path() << ": " << e.what();
    }
    ++replayed;
  }
  return replayed;
}

TEST(FuzzInputs, EverySurfaceInputIsReadOrRefusedAsBadInput) {
  const fs::path fuzz = fs::path(IGAPREP_SOURCE_DIR) / "fuzz";
  const fs::path scratch = fs::path(IGAPREP_BINARY_DIR) / "tests" / "fuzz_inputs";
  fs::create_directories(scratch);
  for (const std::string format : {"stl", "obj", "off", "ply"}) {
    const int seeds = replay(fuzz / "corpus" / format, "." + format, scratch);
    EXPECT_GE(seeds, 4) << format;  // the committed seed corpus
    replay(fuzz / "regressions" / format, "." + format, scratch);
  }
}

}  // namespace
