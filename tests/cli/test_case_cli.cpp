// Case files through the CLI: an error that names the key (the library's
// tests hold the rest), tetmesh, model, midsurface, offset.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <utility>
#include <vector>

#include "cli/cli_runner.h"

namespace {

namespace fs = std::filesystem;

std::string write_case(const std::string& dir, const std::string& json) {
  const std::string path = dir + "/case.json";
  std::ofstream(path) << json;
  return path;
}

std::string surfaces_key() { return R"("surfaces": [")" + models_dir() + R"(/sphere2/outer.off"])"; }

TEST(CaseCli, UnknownKeyIsNamed) {
  const auto dir = scratch_dir("unknown_key");
  const auto path = write_case(dir, "{" + surfaces_key() + R"(, "tetmesh": {"radius_edge": 2}})");
  const auto r = run_cli("tetmesh " + path);
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("unknown key 'tetmesh.radius_edge'"), std::string::npos) << r.out;
}





TEST(CaseCli, TetmeshOfSphere2FillsBothMaterialsAndWritesVtu) {
  const auto dir = scratch_dir("tetmesh");
  const auto r = run_cli("tetmesh " + models_dir() + "/sphere2/case.json -o " + dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(fs::exists(dir + "/tetmesh.vtu"));
  // The printed total volume equals the outer surface's enclosed volume.
  const auto check = run_cli("check-mesh --json " + models_dir() + "/sphere2/outer.off");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex("volume ([0-9.e+-]+) \\(radius-edge")));
  const double tet_volume = std::stod(m[1]);
  std::smatch v;
  ASSERT_TRUE(std::regex_search(check.out, v, std::regex("\"volume\": ([0-9.e+-]+)")));
  EXPECT_NEAR(tet_volume, std::stod(v[1]), 1e-5 * tet_volume);  // printed with 6 digits
  EXPECT_NE(r.out.find("material 0 (shell)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("material 1 (core)"), std::string::npos) << r.out;
}

TEST(CaseCli, ModelCommandWritesExactlyTheCommittedFiles) {
  for (const std::string name : {"sphere2", "ring2", "torus3"}) {
    const auto dir = scratch_dir("model_" + name);
    const auto r = run_cli("model " + name + " -o " + dir);
    ASSERT_EQ(r.exit_code, 0) << r.out;
    int compared = 0;
    for (const auto& entry : fs::directory_iterator(models_dir() + "/" + name)) {
      if (!entry.is_regular_file()) continue;
      const std::string file = entry.path().filename().string();
      EXPECT_EQ(read_all(dir + "/" + file), read_all(entry.path().string())) << name << "/" << file;
      ++compared;
    }
    EXPECT_GE(compared, 2) << name;
  }
}


TEST(CaseCli, UnknownCommandIsAUsageError) {
  const auto r = run_cli("frobnicate");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  // Issue 21, item 14: named, with the documented prefix.
  EXPECT_EQ(r.out.rfind("error: unknown command 'frobnicate' (commands: run, check-mesh, ", 0), 0u) << r.out;
  for (const char* args : {"solve", "offset x.off --inward abc -o y.off", "run --no-such-flag"}) {
    const auto u = run_cli(args);
    EXPECT_EQ(u.exit_code, 1) << args << ": " << u.out;
    EXPECT_EQ(u.out.rfind("error: ", 0), 0u) << args << ": " << u.out;
  }
  const auto help = run_cli("--help");
  EXPECT_EQ(help.exit_code, 0) << help.out;
  EXPECT_EQ(help.out.find("error:"), std::string::npos) << help.out;
}

TEST(CaseCli, VersionNamesTheReleaseAndTheRevision) {
  const auto r = run_cli("--version");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(^igaprep [0-9]+\.[0-9]+\.[0-9]+ \(git [^)]+\)\n$)"))) << r.out;
}

// An output folder that cannot be made is bad input (exit 1), named, not an
// internal failure: /proc takes no new folders, and a file is no folder.
TEST(CaseCli, AnOutputFolderThatCannotBeMadeIsBadInput) {
  const auto dir = scratch_dir("output_folder");
  std::ofstream(dir + "/a_file") << "x";
  for (const std::string& out : {std::string("/proc/igaprep-no-folder"), dir + "/a_file"}) {
    const auto r = run_cli("model sphere2 -o " + out);
    EXPECT_EQ(r.exit_code, 1) << out << ": " << r.out;
    EXPECT_EQ(r.out.rfind("error: ", 0), 0u) << r.out;
    EXPECT_NE(r.out.find("'" + out + "'"), std::string::npos) << r.out;
  }
}

}  // namespace

namespace {


// The decomposition and fit sections: unknown keys and values out of range
// are refused before any work, naming the key.

TEST(CaseCli, MidsurfaceOfRing2PrintsTwoLoopsAndWritesVtu) {
  const auto dir = scratch_dir("midsurface_ring2");
  const auto r = run_cli("midsurface " + models_dir() + "/ring2/case.json -o " + dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("genus 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("loop 1:"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("loop 2:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("with 1 holes"), std::string::npos) << r.out;
  for (const char* f : {"midsurface_t1_regions.vtu", "midsurface_loops.vtu", "midsurface_m0.vtu",
                        "midsurface_m0trim.vtu", "midsurface_rectangles.vtu", "base_surface.vtu"})
    EXPECT_TRUE(fs::exists(dir + "/" + f)) << f;
}

}  // namespace

namespace {


TEST(CaseCli, OffsetTooDeepNamesTheInputFile) {
  const auto r = run_cli("offset " + models_dir() + "/ring2/inner.off --inward 0.3 -o " + std::string(IGAPREP_BINARY_DIR) +
                         "/tests/cli_scratch/too_deep.off");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("ring2/inner.off: "), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(std::string(IGAPREP_BINARY_DIR) + "/tests/cli_scratch/too_deep.off"));
}

// Issue 21, item 2: an output that is one of the inputs (by file identity:
// the same name, a hard link or a symlink) is refused before any work, and
// the input is left as it was.
TEST(CaseCli, AnOutputThatIsTheInputIsRefused) {
  const std::string dir = scratch_dir("replace_input");
  const std::string surface = dir + "/x.off";
  fs::copy_file(models_dir() + "/ring2/outer.off", surface);
  fs::create_symlink(surface, dir + "/link.off");
  const std::string before = read_all(surface);
  for (const std::string& out : {surface, dir + "/link.off", dir + "/../replace_input/x.off"}) {
    const auto r = run_cli("offset " + surface + " --inward 0.05 -o " + out);
    EXPECT_EQ(r.exit_code, 1) << r.out;
    EXPECT_NE(r.out.find("is the input '" + surface + "' (the same file)"), std::string::npos) << r.out;
  }
  EXPECT_EQ(read_all(surface), before);

  // A run whose output folder would take its case file's name.
  const std::string case_dir = scratch_dir("replace_case");
  const std::string case_path = case_dir + "/report.json";
  std::ofstream(case_path) << "{" << surfaces_key() << R"(, "output": ".", "validation": {"enabled": false}})";
  const std::string case_text = read_all(case_path);
  const auto r = run_cli("run " + case_path);
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("output '" + case_dir + "/report.json' is the input"), std::string::npos) << r.out;
  EXPECT_EQ(read_all(case_path), case_text);
}

// Issue 21, item 9: an output folder that is an existing file is bad input,
// said before any work (it used to end the run with an internal failure).
TEST(CaseCli, AnOutputFolderThatIsAFileIsRefusedFirst) {
  const std::string dir = scratch_dir("output_is_file");
  const std::string file = dir + "/taken";
  std::ofstream(file) << "x";
  const auto r = run_cli("run " + write_case(dir, "{" + surfaces_key() + "}") + " -o " + file);
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("output folder '" + file + "' is an existing file, not a folder"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("midsurface"), std::string::npos) << "work was done: " << r.out;
}

}  // namespace
