// Case files through the CLI: errors that name the key, tetmesh, model, run.
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

std::string scratch_dir(const std::string& name) {
  const fs::path dir = fs::path(IGAPREP_BINARY_DIR) / "tests" / "cli_scratch" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::string write_case(const std::string& dir, const std::string& json) {
  const std::string path = dir + "/case.json";
  std::ofstream(path) << json;
  return path;
}

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string surfaces_key() { return R"("surfaces": [")" + models_dir() + R"(/sphere2/outer.off"])"; }

TEST(CaseCli, UnknownKeyIsNamed) {
  const auto dir = scratch_dir("unknown_key");
  const auto path = write_case(dir, "{" + surfaces_key() + R"(, "tetmesh": {"radius_edge": 2}})");
  const auto r = run_cli("tetmesh " + path);
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("unknown key 'tetmesh.radius_edge'"), std::string::npos) << r.out;
}

TEST(CaseCli, WrongTypeIsNamed) {
  const auto dir = scratch_dir("wrong_type");
  const auto path = write_case(dir, "{" + surfaces_key() + R"(, "tetmesh": {"max_volume": "big"}})");
  const auto r = run_cli("tetmesh " + path);
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("'tetmesh.max_volume' must be a number"), std::string::npos) << r.out;
}

TEST(CaseCli, MissingSurfaceFileIsNamed) {
  const auto dir = scratch_dir("missing_file");
  const auto path = write_case(dir, R"({"surfaces": ["nowhere.stl"]})");
  const auto r = run_cli("tetmesh " + path);
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("surfaces[0]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("nowhere.stl"), std::string::npos) << r.out;
}

TEST(CaseCli, MaterialCountMustMatchSurfaces) {
  const auto dir = scratch_dir("materials");
  const auto path = write_case(dir, "{" + surfaces_key() +
      R"(, "materials": [{"name": "a", "young_modulus": 1, "poisson_ratio": 0.3}, {"name": "b", "young_modulus": 1, "poisson_ratio": 0.3}]})");
  const auto r = run_cli("tetmesh " + path);
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("'materials' has 2 entries but there are 1 surfaces"), std::string::npos) << r.out;
}

TEST(CaseCli, PoissonRatioOfOneHalfIsRefused) {
  const auto dir = scratch_dir("poisson");
  const auto path = write_case(dir, "{" + surfaces_key() +
      R"(, "materials": [{"name": "a", "young_modulus": 1, "poisson_ratio": 0.5}]})");
  const auto r = run_cli("tetmesh " + path);
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("materials[0].poisson_ratio"), std::string::npos) << r.out;
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

TEST(CaseCli, RunWithoutCaseUsesTheDefaultModel) {
  const auto dir = scratch_dir("run_default");
  const auto r = run_cli("run -o " + dir);
  // 0: the model passed every check; 2: it was made but a check failed
  // (docs/decomposition.md, "Known limits").
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 2) << r.out;
  EXPECT_NE(r.out.find("case 'ring2'"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("tetmesh"), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::exists(dir + "/model.h5")) << r.out;
  EXPECT_TRUE(std::filesystem::exists(dir + "/report.json")) << r.out;
}

TEST(CaseCli, UnknownCommandIsAUsageError) {
  const auto r = run_cli("frobnicate");
  EXPECT_EQ(r.exit_code, 1) << r.out;
}

}  // namespace

namespace {

TEST(CaseCli, MidsurfaceSectionIsParsedAndItsUnknownKeysNamed) {
  const auto dir = scratch_dir("midsurface_keys");
  const auto path = write_case(dir, "{" + surfaces_key() + R"(, "midsurface": {"m0": 0.4, "colour": 1}})");
  const auto r = run_cli("midsurface " + path);
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("colour"), std::string::npos) << r.out;
}

// The decomposition and fit sections: unknown keys and values out of range
// are refused before any work, naming the key.
TEST(CaseCli, DecompositionAndFitKeysAreChecked) {
  const std::vector<std::pair<std::string, std::string>> bad = {
      {R"("decomposition": {"colour": 1})", "decomposition.colour"},
      {R"("decomposition": {"strategy": 3})", "decomposition.strategy"},
      {R"("decomposition": {"strategy": 1.5})", "decomposition.strategy"},
      {R"("decomposition": {"theta": 2.0})", "decomposition.theta"},
      {R"("decomposition": {"inset": 1.0})", "decomposition.inset"},
      {R"("decomposition": {"smoothing": -1})", "decomposition.smoothing"},
      {R"("decomposition": {"surface_degree": 2.5})", "decomposition.surface_degree"},
      {R"("decomposition": {"surface_degree": 13})", "decomposition.surface_degree"},
      {R"("decomposition": {"sliding_uv": "yes"})", "decomposition.sliding_uv"},
      {R"("fit": {"elements": 0})", "fit.elements"},
      {R"("fit": {"degree": 2.5})", "fit.degree"},
      {R"("fit": {"knots": 3})", "fit.knots"},
      {R"("fit": {"jacobian_target": 0.95})", "fit.jacobian_target"},
      {R"("fit": {"jacobian_sweeps": 2.5})", "fit.jacobian_sweeps"},
      {R"("fit": {"jacobian_points": 1})", "fit.jacobian_points"},
  };
  for (const auto& [section, key] : bad) {
    const auto dir = scratch_dir("volume_keys");
    const auto path = write_case(dir, "{" + surfaces_key() + ", " + section + "}");
    const auto r = run_cli("run " + path + " -o " + dir + "/out");
    EXPECT_EQ(r.exit_code, 1) << section << "\n" << r.out;
    EXPECT_NE(r.out.find(key), std::string::npos) << section << "\n" << r.out;
    EXPECT_EQ(r.out.find("tetmesh "), std::string::npos) << "refused before any stage: " << r.out;
  }
}

TEST(CaseCli, MidsurfaceOfRing2PrintsTwoLoopsAndWritesVtu) {
  const auto dir = scratch_dir("midsurface_ring2");
  const auto r = run_cli("midsurface " + models_dir() + "/ring2/case.json -o " + dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("genus 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("loop 1:"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("loop 2:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("with 1 holes"), std::string::npos) << r.out;
  for (const char* f : {"midsurface_t1_regions.vtu", "midsurface_loops.vtu", "midsurface_m0.vtu",
                        "midsurface_m0trim.vtu", "midsurface_rectangles.vtu", "midsurface_base.vtu"})
    EXPECT_TRUE(fs::exists(dir + "/" + f)) << f;
}

}  // namespace

namespace {

TEST(CaseCli, RadiusEdgeRatioOfOneIsRefused) {
  const auto dir = scratch_dir("radius_edge");
  const auto path = write_case(dir, "{" + surfaces_key() + R"(, "tetmesh": {"radius_edge_ratio": 1.0}})");
  const auto r = run_cli("tetmesh " + path);
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("greater than 1.0"), std::string::npos) << r.out;
}

TEST(CaseCli, OffsetTooDeepNamesTheInputFile) {
  const auto r = run_cli("offset " + models_dir() + "/ring2/inner.off --inward 0.3 -o " + std::string(IGAPREP_BINARY_DIR) +
                         "/tests/cli_scratch/too_deep.off");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("ring2/inner.off: "), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(std::string(IGAPREP_BINARY_DIR) + "/tests/cli_scratch/too_deep.off"));
}

}  // namespace
