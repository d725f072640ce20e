// `igaprep run` end to end on the built-in models (issue 9's acceptance):
// the run's own report (report.json) and the model it wrote (model.h5, read
// back with the library), checked against the issue's numbers. Strategy 2
// unless said otherwise.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/cli_runner.h"
#include "igaprep/export/hdf5_model.h"
#include "igaprep/spline/curve_surface.h"
#include "igaprep/spline/multipatch_topology.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using igaprep::spline::MultiPatch;

struct ModelRun {
  CliResult cli;
  json report;
  MultiPatch model;
  int rectangles = -1, segments = -1;
};

// Runs the model's committed case (plus an optional replacement case text)
// into a scratch folder and loads what it wrote.
ModelRun run_model(const std::string& name, const std::string& case_text = "") {
  const fs::path dir = fs::path(IGAPREP_BINARY_DIR) / "tests" / "pipeline_scratch" / (name + (case_text.empty() ? "" : "_custom"));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::string case_path = models_dir() + "/" + name + "/case.json";
  if (!case_text.empty()) {
    case_path = (dir / "case.json").string();
    std::ofstream(case_path) << case_text;
  }
  ModelRun r;
  r.cli = run_cli("run " + case_path + " -o " + (dir / "out").string());
  std::ifstream in(dir / "out" / "report.json");
  if (in) r.report = json::parse(in);
  if (fs::exists(dir / "out" / "model.h5")) r.model = igaprep::exporter::read_hdf5_model((dir / "out" / "model.h5").string());
  std::smatch m;
  if (std::regex_search(r.cli.out, m, std::regex(R"(M: (\d+) rectangles, (\d+) boundary segments)")))
    r.rectangles = std::stoi(m[1]), r.segments = std::stoi(m[2]);
  return r;
}

double model_diagonal(const MultiPatch& mp) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (const auto& p : mp.patches) {
    lo = lo.cwiseMin(p.control_points.colwise().minCoeff().transpose());
    hi = hi.cwiseMax(p.control_points.colwise().maxCoeff().transpose());
  }
  return (hi - lo).norm();
}

// What holds on every model: the run made a model, the topology is right
// (conforming to 1e-12, every side an interface or labelled), each patch has
// one material, the interfaces between materials lie on the Ti, the fidelity
// and the volumes are within 0.5 %, the patch count follows the layout, and
// the manufactured solution converges at p + 0.5 or better.
void expect_model_facts(const ModelRun& r, int surfaces) {
  ASSERT_TRUE(r.cli.exit_code == 0 || r.cli.exit_code == 2) << r.cli.out;
  ASSERT_FALSE(r.report.is_null()) << r.cli.out;
  const MultiPatch& mp = r.model;
  ASSERT_GT(mp.patches.size(), 0u);
  const double diag = model_diagonal(mp);

  const auto conformity = igaprep::spline::check_conformity(mp, 1e-12 * diag);
  EXPECT_TRUE(conformity.conforming) << (conformity.problems.empty() ? "" : conformity.problems.front());
  EXPECT_EQ(2 * mp.interfaces.size() + mp.boundaries.size(), 6 * mp.patches.size())
      << "every side is an interface or a labelled boundary";
  for (const auto& b : mp.boundaries) EXPECT_EQ(b.label, 0) << "boundary sides lie on T1";
  for (const auto& p : mp.patches) {
    EXPECT_GE(p.material, 0);
    EXPECT_LT(p.material, surfaces);
  }
  int material_interfaces = 0;
  for (const auto& itf : mp.interfaces) {
    const int ma = mp.patches[itf.patch_a].material, mb = mp.patches[itf.patch_b].material;
    if (ma == mb) continue;
    ++material_interfaces;
    EXPECT_EQ(std::abs(ma - mb), 1);
    EXPECT_EQ(itf.surface, std::max(ma, mb)) << "an interface between materials i-1 and i lies on T(i+1)";
  }
  if (surfaces > 1) EXPECT_GT(material_interfaces, 0);

  const json& fig = r.report.at("pipeline").at("figures");
  for (const auto& f : r.report.at("fidelity")) {
    const std::string label = f.at("label");
    EXPECT_LE(fig.at("fidelity_relative_" + label).get<double>(), 0.005) << label;
    if (f.at("surface").get<int>() > 0) EXPECT_GT(f.at("interface_faces").get<int>(), 0) << label;
  }
  ASSERT_EQ(r.report.at("topology").at("regions").size(), static_cast<std::size_t>(surfaces));
  for (const auto& region : r.report.at("topology").at("regions"))
    EXPECT_LE(std::abs(region.at("relative_difference").get<double>()), 0.005);

  // Patches: per rectangle a core block above and below M, per boundary
  // segment a crest block; per outer core face (2 per rectangle, 2 per
  // segment) one shell block per material layer. Nothing depends on the mesh.
  ASSERT_GT(r.rectangles, 0);
  EXPECT_EQ(static_cast<int>(mp.patches.size()),
            2 * r.rectangles + r.segments + (2 * r.rectangles + 2 * r.segments) * surfaces);

  const json& v = r.report.at("pipeline").at("validation");
  ASSERT_TRUE(v.at("ran").get<bool>());
  EXPECT_GE(v.at("l2_rate").get<double>(), 3.5);
  EXPECT_LT(v.at("levels").at(1).at("l2_error").get<double>(), v.at("levels").at(0).at("l2_error").get<double>());
}

// Every element certified positive (none negative, degenerate or
// undecided) and the smallest scaled Jacobian at least min_scaled_jacobian.
void expect_certified(const json& summary, double min_scaled_jacobian) {
  EXPECT_EQ(summary.at("negative").get<int>(), 0);
  EXPECT_EQ(summary.at("undecided").get<int>(), 0);
  EXPECT_EQ(summary.at("degenerate").get<int>(), 0);
  EXPECT_EQ(summary.at("positive").get<int>(), summary.at("elements").get<int>());
  EXPECT_GE(summary.at("min_scaled_jacobian").get<double>(), min_scaled_jacobian);
}

// Runs a model's case, checks what holds on every model and its layout's
// rectangle and boundary-segment counts.
ModelRun run_model_with_layout(const std::string& name, int surfaces, int rectangles, int segments) {
  ModelRun r = run_model(name);
  expect_model_facts(r, surfaces);
  EXPECT_EQ(r.rectangles, rectangles);
  EXPECT_EQ(r.segments, segments);
  return r;
}

TEST(PipelineModels, Sphere2MeetsEveryCriterion) {
  const ModelRun r = run_model_with_layout("sphere2", 2, 1, 4);
  EXPECT_EQ(r.cli.exit_code, 0) << r.cli.out;
  expect_certified(r.report.at("summary"), 0.2);
}

// ring2 and torus3 meet every criterion too. Before optimize_jacobians
// (fit.jacobian_target 0) ring2's smallest scaled Jacobian was 0.14 and
// torus3 had 21 negative elements, at corners of the core's faces
// (docs/decomposition.md).
// What optimize_jacobians reported: the fitted model's lowest sampled
// scaled Jacobian was below `fitted_below`, and after it none is below the
// target (0.35), with some control points moved.
void expect_jacobians_raised(const ModelRun& r, double fitted_below) {
  const json& fig = r.report.at("pipeline").at("figures");
  EXPECT_LT(fig.at("fit_min_scaled_jacobian").get<double>(), fitted_below);
  EXPECT_GE(fig.at("optimized_min_scaled_jacobian").get<double>(), 0.35 - 1e-9);
  EXPECT_GT(fig.at("optimized_control_points").get<int>(), 0);
}

TEST(PipelineModels, Ring2MeetsEveryCriterion) {
  const ModelRun r = run_model_with_layout("ring2", 2, 8, 16);
  EXPECT_EQ(r.cli.exit_code, 0) << r.cli.out;
  expect_certified(r.report.at("summary"), 0.2);
  expect_jacobians_raised(r, 0.2);
}

TEST(PipelineModels, Torus3MeetsEveryCriterion) {
  const ModelRun r = run_model_with_layout("torus3", 1, 18, 32);
  EXPECT_EQ(r.cli.exit_code, 0) << r.cli.out;
  expect_certified(r.report.at("summary"), 0.2);
  expect_jacobians_raised(r, 0.0);
}

// Strategy 1 (no core, the crest volumes are fans collapsed onto M's
// boundary): completes; the elements on the collapsed sides (4 fans x 6 x 6)
// are reported as degenerate, none as negative, and the collapsed sides are
// not unmatched sides.
TEST(PipelineModels, Sphere2Strategy1Completes) {
  std::ifstream in(models_dir() + "/sphere2/case.json");
  json c = json::parse(in);
  for (auto& s : c["surfaces"]) s["file"] = models_dir() + "/sphere2/" + s["file"].get<std::string>();
  c["decomposition"] = {{"strategy", 1}};
  c["validation"] = {{"enabled", false}};
  const ModelRun r = run_model("sphere2", c.dump());
  ASSERT_TRUE(r.cli.exit_code == 0 || r.cli.exit_code == 2) << r.cli.out;
  EXPECT_NE(r.cli.out.find("strategy 1"), std::string::npos);
  const json& s = r.report.at("summary");
  EXPECT_EQ(s.at("degenerate").get<int>(), 4 * 6 * 6);
  EXPECT_EQ(s.at("negative").get<int>(), 0);
  EXPECT_EQ(s.at("undecided").get<int>(), 0);
  EXPECT_EQ(r.report.at("pipeline").at("figures").at("unmatched_sides").get<int>(), 0);
  // 1 rectangle x 2 sides + 4 fans, times 2 layers.
  EXPECT_EQ(r.model.patches.size(), 12u);
}

}  // namespace
