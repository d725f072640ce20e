// pipeline::run end to end on the built-in models (issue 9's acceptance and
// issue 17's library): the returned model and report checked against the
// method's numbers. Strategy 2 unless said otherwise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>

#include "igaprep/core/error.h"
#include "igaprep/export/hdf5_model.h"
#include "igaprep/pipeline/validation.h"
#include "igaprep/spline/multipatch_topology.h"
#include "pipeline_runs.h"

namespace {

using igaprep::pipeline::RunResult;
using igaprep::spline::MultiPatch;
using nlohmann::json;
using pipeline_test::model_case;
using pipeline_test::Recorder;

double figure(const RunResult& r, const std::string& name) {
  for (const auto& [key, value] : r.report.pipeline->figures)
    if (key == name) return value;
  ADD_FAILURE() << "no figure " << name;
  return std::nan("");
}

double model_diagonal(const MultiPatch& mp) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (const auto& p : mp.patches) {
    lo = lo.cwiseMin(p.control_points.colwise().minCoeff().transpose());
    hi = hi.cwiseMax(p.control_points.colwise().maxCoeff().transpose());
  }
  return (hi - lo).norm();
}

// What holds on every model: conforming to 1e-12, every side an interface or
// labelled, a material per patch, interfaces between materials on the Ti,
// fidelity and volumes within 0.5 %, the patch count from the layout, and the
// manufactured solution converging at p + 0.5 or better.
void expect_model_facts(const RunResult& r, int surfaces) {
  const MultiPatch& mp = r.model;
  ASSERT_GT(mp.patches.size(), 0u);
  const auto conformity = igaprep::spline::check_conformity(mp, 1e-12 * model_diagonal(mp));
  EXPECT_TRUE(conformity.conforming) << (conformity.problems.empty() ? "" : conformity.problems.front());
  EXPECT_EQ(2 * mp.interfaces.size() + mp.boundaries.size(), 6 * mp.patches.size())
      << "every side is an interface or a labelled boundary";
  for (const auto& b : mp.boundaries) EXPECT_EQ(b.label, 0) << "boundary sides lie on T1";
  int material_interfaces = 0;
  for (const auto& itf : mp.interfaces) {
    const int ma = mp.patches[itf.patch_a].material, mb = mp.patches[itf.patch_b].material;
    if (ma == mb) continue;
    ++material_interfaces;
    EXPECT_EQ(std::abs(ma - mb), 1);
    EXPECT_EQ(itf.surface, std::max(ma, mb)) << "an interface between materials i-1 and i lies on T(i+1)";
  }
  if (surfaces > 1) EXPECT_GT(material_interfaces, 0);
  ASSERT_EQ(static_cast<int>(mp.labels.size()), surfaces);
  for (const auto& label : mp.labels) EXPECT_LE(figure(r, "fidelity_relative_" + label), 0.005) << label;
  ASSERT_EQ(r.report.topology.regions.size(), static_cast<std::size_t>(surfaces));
  for (const auto& region : r.report.topology.regions) EXPECT_LE(std::abs(region.relative_difference), 0.005);
  // Per rectangle a core block above and below M, per boundary segment a
  // crest block; per outer core face (2 per rectangle, 2 per segment) one
  // shell block per material layer.
  EXPECT_EQ(static_cast<int>(mp.patches.size()),
            2 * r.rectangles + r.boundary_segments + (2 * r.rectangles + 2 * r.boundary_segments) * surfaces);
  const auto& v = r.report.pipeline->validation;
  ASSERT_TRUE(v && v->ran);
  EXPECT_GE(v->l2_rate, 3.5);
  EXPECT_LT(v->levels.at(1).l2_error, v->levels.at(0).l2_error);
}

// Every element certified positive and the smallest scaled Jacobian at least `min`.
void expect_certified(const RunResult& r, double min) {
  EXPECT_TRUE(r.passed) << r.report.pipeline->verdict;
  EXPECT_EQ(figure(r, "negative_elements"), 0.0);
  EXPECT_EQ(figure(r, "undecided_elements"), 0.0);
  EXPECT_EQ(figure(r, "degenerate_elements"), 0.0);
  EXPECT_EQ(figure(r, "positive_elements"), figure(r, "elements"));
  EXPECT_GE(figure(r, "min_scaled_jacobian"), min);
}

// optimize_jacobians: the fitted model's lowest sampled scaled Jacobian was
// below `fitted_below`, and after it none is below the target (0.35).
void expect_jacobians_raised(const RunResult& r, double fitted_below) {
  EXPECT_LT(figure(r, "fit_min_scaled_jacobian"), fitted_below);
  EXPECT_GE(figure(r, "optimized_min_scaled_jacobian"), 0.35 - 1e-9);
  EXPECT_GT(figure(r, "optimized_control_points"), 0.0);
}

// sphere2 with every output: exports, a one-patch validation and a load case fixing
// the outer sides with centre x < -0.3 and pressing on those with x > 0.3.
TEST(PipelineModels, Sphere2MeetsEveryCriterionAndWritesItsOutputs) {
  const auto c = model_case("sphere2", R"({"export": ["gismo", "mfem", "vtu", "bext"], "validation": {"patches": 1},
      "load_case": {"fix": {"label": "outer", "box": [[-2, -2, -2], [-0.3, 2, 2]]},
                    "pressure": {"label": "outer", "value": 1.0, "box": [[0.3, -2, -2], [2, 2, 2]]}}})");
  Recorder rec;
  rec.wanted = {"tetmesh", "base_surface", "decomposition_w"};
  const RunResult r = igaprep::pipeline::run(c, rec);
  EXPECT_EQ(rec.received, rec.wanted) << "the intermediates asked for, in the order made, and no other";
  expect_model_facts(r, 2);
  expect_certified(r, 0.2);
  EXPECT_EQ(r.rectangles, 1);
  EXPECT_EQ(r.boundary_segments, 4);
  const std::vector<std::string> stages = {"validate", "midsurface", "base", "decompose", "param", "fit",
                                           "check", "export", "validation", "load_case"};
  EXPECT_EQ(rec.stage_names(), stages);
  ASSERT_EQ(r.report.pipeline->stages.size(), stages.size());
  // The load case: positive energy, and result.h5 carries the same figures.
  ASSERT_TRUE(r.load_case);
  EXPECT_GT(r.load_case->strain_energy, 0.0);
  EXPECT_GT(r.load_case->max_displacement, 0.0);
  const MultiPatch result = igaprep::exporter::read_hdf5_model(c.output_dir + "/result.h5");
  EXPECT_EQ(result.strain_energy, r.load_case->strain_energy);
  EXPECT_EQ(result.max_displacement, r.load_case->max_displacement);
  for (const char* f : {"model.h5", "model.xml", "model.mesh", "model.vtu", "model_boundary.vtu", "result.h5",
                        "report.json", "report.html", "run.pvd"})
    EXPECT_TRUE(pipeline_test::fs::exists(c.output_dir + "/" + f)) << f;
  // LS-DYNA: the deck and one BEXT file per material (issue 23: 564 MB when
  // each element carried its own extraction operator). 14.4 MB, not the
  // issue's 10: each part file carries its own copy of the 2,320 shared
  // coefficient vectors (3.4 MB each in 24-column reals), and sparse blocks,
  // whose layout no public source gives, are not written (docs/export-formats.md).
  std::uintmax_t bext_bytes = 0;
  for (const char* f : {"model_part1.bext", "model_part2.bext"}) {
    ASSERT_TRUE(pipeline_test::fs::exists(c.output_dir + "/" + f)) << f;
    bext_bytes += pipeline_test::fs::file_size(c.output_dir + "/" + f);
  }
  EXPECT_LT(bext_bytes, 14'500'000u);
  EXPECT_GT(bext_bytes, 1'000'000u);  // 5,616 elements of degree 3 do not fit in less
  EXPECT_TRUE(pipeline_test::fs::exists(c.output_dir + "/model.k"));
  // run.pvd groups the VTU files for ParaView, the model first (issue 23, item 2).
  std::ifstream pvd(c.output_dir + "/run.pvd");
  const std::string collection((std::istreambuf_iterator<char>(pvd)), std::istreambuf_iterator<char>());
  EXPECT_NE(collection.find("<VTKFile type=\"Collection\""), std::string::npos) << collection;
  const std::size_t model_at = collection.find("file=\"model.vtu\""),
                    boundary_at = collection.find("file=\"model_boundary.vtu\"");
  EXPECT_NE(model_at, std::string::npos) << collection;
  EXPECT_NE(boundary_at, std::string::npos) << collection;
  EXPECT_LT(model_at, boundary_at);
  // The model on disk is the model returned, with its provenance.
  const MultiPatch disk = igaprep::exporter::read_hdf5_model(c.output_dir + "/model.h5");
  ASSERT_EQ(disk.patches.size(), r.model.patches.size());
  EXPECT_EQ(disk.patches.back().control_points, r.model.patches.back().control_points);
  EXPECT_EQ(disk.provenance_case, c.text);
  EXPECT_EQ(disk.provenance_generator.rfind("igaprep 0.", 0), 0u) << disk.provenance_generator;
  const json inputs = json::parse(disk.provenance_inputs);
  EXPECT_EQ(inputs.at("surfaces").at(0).at("sha256").get<std::string>().size(), 64u);
  EXPECT_EQ(inputs.at("options").at("fit").at("elements").get<int>(), 6);
  EXPECT_EQ(inputs.at("date").get<std::string>().size(), 20u);  // 2026-12-01T20:00:00Z
}

// A built-in model's committed case with `extra` keys, run without writing:
// certified with min scaled Jacobian >= 0.2, its layout's counts,
// optimize_jacobians' raise from below `fitted_below`.
void expect_model_meets_every_criterion(const std::string& name, int surfaces, int rectangles, int segments,
                                        double fitted_below, const std::string& extra = "{}") {
  Recorder rec;
  const RunResult r = igaprep::pipeline::run(model_case(name, extra), rec, {"", false});
  expect_model_facts(r, surfaces);
  EXPECT_EQ(r.rectangles, rectangles);
  EXPECT_EQ(r.boundary_segments, segments);
  expect_certified(r, 0.2);
  expect_jacobians_raised(r, fitted_below);
  for (const auto& c : r.report.criteria) EXPECT_TRUE(c.passed) << c.name << ": " << c.summary;
  // The param stage's sample grids lose no part of the input (block_coverage.h).
  for (const auto& s : rec.stages)
    if (s.stage == "param")
      for (const auto& line : s.details) EXPECT_EQ(line.find("folded"), 0u) << line;
}

TEST(PipelineModels, Ring2MeetsEveryCriterion) { expect_model_meets_every_criterion("ring2", 2, 8, 16, 0.2); }

// torus3's validation on one patch: ring2's test covers the study across
// interfaces, and torus3's 4-patch study (27,885 unknowns at the finer level)
// would be a third of the suite's time.
TEST(PipelineModels, Torus3MeetsEveryCriterion) {
  expect_model_meets_every_criterion("torus3", 1, 18, 32, 0.0, R"({"validation": {"patches": 1}})");
}

// A shape that is not built in: a smooth plate 1 x 0.6 x 0.06 with round
// rims and two round holes (genus 2; tests/data/mesh/thin_plate_two_holes.off,
// made by `scripts/thin_plates.py plate 0.06 0.9`), every key at its default
// but 12 elements per direction and the validation on one patch. At the
// default 6 elements its volume is -0.81 % (the cubic rings where the flat
// faces meet the rims, docs/validation.md "Thin plates"); at 12 it passes:
// 2026-12-06, min scaled Jacobian 0.338, fidelity 0.244 %, volume -0.365 %.
TEST(PipelineModels, AThinPlateWithTwoHolesMeetsEveryCriterionAt12Elements) {
  const std::string off = std::string(IGAPREP_TEST_DATA_DIR) + "/mesh/thin_plate_two_holes.off";
  const igaprep::pipeline::Case c = igaprep::pipeline::parse_case(
      R"({"surfaces": [")" + off + R"("], "fit": {"elements": 12}, "validation": {"patches": 1}, "output": ")" +
          pipeline_test::scratch_dir("thin_plate_run") + R"("})",
      pipeline_test::scratch_dir("thin_plate_case"), "thin_plate/case.json");
  Recorder rec;
  const RunResult r = igaprep::pipeline::run(c, rec, {"", false});
  expect_model_facts(r, 1);
  expect_certified(r, 0.3);
  for (const auto& criterion : r.report.criteria) EXPECT_TRUE(criterion.passed) << criterion.name << ": " << criterion.summary;
  EXPECT_LE(figure(r, "fidelity_relative_thin_plate_two_holes"), 0.003);
  ASSERT_EQ(r.report.topology.regions.size(), 1u);
  EXPECT_GT(r.report.topology.regions[0].relative_difference, -0.0045);
  EXPECT_LT(r.report.topology.regions[0].relative_difference, 0.0);
}

// Strategy 1 (no core, the crest volumes are fans collapsed onto M's
// boundary): completes; the elements on the collapsed sides (4 fans x 6 x 6)
// are degenerate, none negative, and the collapsed sides are not unmatched.
// Its load case is not solved on a model with degenerate elements, and says so.
TEST(PipelineModels, Sphere2Strategy1Completes) {
  Recorder rec;
  const RunResult r = igaprep::pipeline::run(
      model_case("sphere2", R"({"decomposition": {"strategy": 1}, "validation": {"enabled": false},
          "load_case": {"fix": {"label": "outer", "box": [[-2, -2, -2], [-0.3, 2, 2]]},
                        "force": {"label": "outer", "value": [1, 0, 0], "box": [[0.3, -2, -2], [2, 2, 2]]}}})",
                 "sphere2_strategy1"),  // its own folder: ctest runs the tests in parallel
      rec,
      {"", false});
  EXPECT_FALSE(r.load_case);
  ASSERT_EQ(rec.stages.back().stage, "load_case");
  EXPECT_EQ(rec.stages.back().headline.rfind("not solved: ", 0), 0u) << rec.stages.back().headline;
  EXPECT_NE(rec.stages.at(4).headline.find("strategy 1"), std::string::npos) << rec.stages.at(4).headline;
  EXPECT_EQ(figure(r, "degenerate_elements"), 4 * 6 * 6);
  EXPECT_EQ(figure(r, "negative_elements"), 0.0);
  EXPECT_EQ(figure(r, "undecided_elements"), 0.0);
  EXPECT_EQ(figure(r, "unmatched_sides"), 0.0);
  EXPECT_FALSE(r.passed);
  EXPECT_EQ(r.model.patches.size(), 12u);  // 1 rectangle x 2 sides + 4 fans, times 2 layers
}

// fit.surface_iterations: the faces on both of sphere2's surfaces fitted to
// them (fit_model_surface) after the volume fit; the pairs come closer, the
// model stays conforming with every side labelled or on an interface.
TEST(PipelineModels, Sphere2FacesFittedToTheirSurfaces) {
  Recorder rec;
  const RunResult r = igaprep::pipeline::run(
      model_case("sphere2", R"({"fit": {"elements": 3, "jacobian_target": 0, "surface_iterations": 3},
          "validation": {"enabled": false}})", "sphere2_surface_fit"),
      rec, {"", false});
  for (const std::string i : {"0", "1"}) {
    const double before = figure(r, "surface_fit_rms_before_" + i), after = figure(r, "surface_fit_rms_after_" + i);
    EXPECT_LT(after, 0.9 * before) << i << ": " << before << " -> " << after;  // 0.72 and 0.78 on 2026-12-03
  }
  const auto conformity = igaprep::spline::check_conformity(r.model, 1e-12 * model_diagonal(r.model));
  EXPECT_TRUE(conformity.conforming);
  EXPECT_EQ(figure(r, "unmatched_sides"), 0.0);
  EXPECT_EQ(figure(r, "negative_elements"), 0.0);
}

// A load case whose box holds no side is bad input naming the key; the
// model and the report of what ran are kept, with the error as verdict.
TEST(PipelineModels, LoadCaseBoxWithoutSidesIsNamedAndTheReportKept) {
  const auto c = model_case("sphere2", R"({"fit": {"elements": 3, "jacobian_target": 0},
      "validation": {"enabled": false},
      "load_case": {"fix": {"label": "outer", "box": [[5, 5, 5], [6, 6, 6]]}}})", "empty_box");
  Recorder rec;
  try {
    igaprep::pipeline::run(c, rec);
    ADD_FAILURE() << "no error";
  } catch (const igaprep::Error& e) {
    EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput);
    EXPECT_NE(std::string(e.what()).find("'load_case.fix[0].box': none of the"), std::string::npos) << e.what();
  }
  ASSERT_TRUE(pipeline_test::fs::exists(c.output_dir + "/model.h5"));
  EXPECT_FALSE(pipeline_test::fs::exists(c.output_dir + "/result.h5"));
  std::ifstream in(c.output_dir + "/report.json");
  const json p = json::parse(in).at("pipeline");
  EXPECT_TRUE(p.at("validation").is_null());
  EXPECT_EQ(p.at("verdict").get<std::string>().rfind("ERROR: load case", 0), 0u) << p.dump(2);
}

}  // namespace

namespace {

// The load case's total force and rotation reach the solve: the strain
// energy is quadratic in the force and in omega^2 (to round-off), the two
// together give the energies' sum plus the cross term, and a force split
// over two boxes does what the one force does.
TEST(PipelineModels, ForceAndRotationLoadsReachTheSolve) {
  const auto c = model_case("sphere2", R"({"fit": {"elements": 2, "jacobian_target": 0},
      "validation": {"enabled": false}})", "sphere2_loads");
  igaprep::pipeline::Observer quiet;
  const RunResult r = igaprep::pipeline::run(c, quiet, {"", false});
  using igaprep::pipeline::CaseLoadCase;
  auto energy = [&](const CaseLoadCase& lc) {
    return igaprep::pipeline::load_case_stage(r.model, lc, quiet).solution.report.strain_energy;
  };
  CaseLoadCase lc;
  lc.fix = {{{"outer", std::array<Eigen::Vector3d, 2>{Eigen::Vector3d(-2, -2, -2), Eigen::Vector3d(-0.3, 2, 2)}}}};
  const auto right = std::array<Eigen::Vector3d, 2>{Eigen::Vector3d(0.3, -2, -2), Eigen::Vector3d(2, 2, 2)};
  lc.force = {{{"outer", right}, Eigen::Vector3d(0.0, 0.0, -1.0)}};
  const double f1 = energy(lc);
  lc.force[0].value *= 2.0;
  EXPECT_NEAR(energy(lc), 4.0 * f1, 1e-10 * f1);
  EXPECT_GT(f1, 0.0);
  // The same force as two entries of half the force each on the same box.
  lc.force = {{{"outer", right}, Eigen::Vector3d(0.0, 0.0, -0.5)}, {{"outer", right}, Eigen::Vector3d(0.0, 0.0, -0.5)}};
  EXPECT_NEAR(energy(lc), f1, 1e-10 * f1);
  lc.force.clear();
  lc.rotation = igaprep::iga_check::RotationLoad{1.0, 0.5, Eigen::Vector3d::UnitX(), Eigen::Vector3d::Zero()};
  const double w1 = energy(lc);
  lc.rotation->angular_velocity = 1.0;
  EXPECT_NEAR(energy(lc), 16.0 * w1, 1e-10 * w1);
  EXPECT_GT(w1, 0.0);
}

// A model with only positive elements that misses part of the solid fails the
// run: one element per direction leaves sphere2 2.2 % off its outer surface
// (its samples too far apart to follow it; the param stage is kept from
// spreading them, which would take it to 1.3 %).
TEST(PipelineModels, AModelOffItsSurfacesFailsTheRunNamingTheFigures) {
  const auto c = model_case("sphere2", R"({"fit": {"elements": 1, "jacobian_target": 0},
      "decomposition": {"spread_deviation": 0, "cover_rounds": 0}, "validation": {"enabled": false}})", "sphere2_coarse");
  igaprep::pipeline::Observer quiet;
  const RunResult r = igaprep::pipeline::run(c, quiet, {"", false});
  EXPECT_FALSE(r.report.passed);
  EXPECT_FALSE(r.passed);
  ASSERT_EQ(r.report.criteria.size(), 5u);
  EXPECT_EQ(r.report.criteria[0].name, "jacobian");
  EXPECT_TRUE(r.report.criteria[0].passed) << "every element positive";
  const std::string& verdict = r.report.pipeline->verdict;
  EXPECT_EQ(verdict.rfind("FAIL: check FAILED (fidelity", 0), 0u) << verdict;
  EXPECT_NE(r.report.verdict.find("fidelity: largest distance between an input surface and the model 2."),
            std::string::npos) << r.report.verdict;
  EXPECT_GT(figure(r, "fidelity_relative_outer"), 0.005);
}

// sphere2 fitted with 2 elements per direction: its 4 patches' L2 rate at
// refine 0/1 is 2.86, before the asymptotic range; measured once more at
// 1/2 it is 4.12 (2026-12-07). With 'finer_when_missed' off the study
// stays at 0/1 and misses.
TEST(PipelineValidation, ARateMissedAtTheCaseLevelsIsMeasuredALevelFiner) {
  const std::string keys = R"({"fit": {"elements": 2, "jacobian_target": 0}, "decomposition": {"cover_rounds": 0},
                              "export": [], "validation": {"finer_when_missed": )";
  Recorder rec;
  const RunResult r = igaprep::pipeline::run(model_case("sphere2", keys + "true}}", "finer_study"), rec, {"", false});
  const auto& v = r.report.pipeline->validation;
  ASSERT_TRUE(v && v->ran);
  ASSERT_EQ(v->levels.size(), 2u);
  EXPECT_EQ(v->levels[0].refine, 1);
  EXPECT_EQ(v->levels[1].refine, 2);
  EXPECT_GT(v->first_l2_rate, 2.5);
  EXPECT_LT(v->first_l2_rate, 3.2);
  EXPECT_GE(v->l2_rate, 3.5);
  EXPECT_TRUE(v->met);
  const auto stage = std::find_if(rec.stages.begin(), rec.stages.end(), [](const auto& s) { return s.stage == "validation"; });
  ASSERT_NE(stage, rec.stages.end());
  ASSERT_EQ(stage->details.size(), 1u);
  EXPECT_NE(stage->details[0].find("at refine 0/1 the L2 rate was"), std::string::npos) << stage->details[0];

  Recorder off;
  const RunResult r0 = igaprep::pipeline::run(model_case("sphere2", keys + "false}}", "finer_study_off"), off, {"", false});
  const auto& v0 = r0.report.pipeline->validation;
  ASSERT_TRUE(v0 && v0->ran);
  EXPECT_EQ(v0->levels.at(0).refine, 0);
  EXPECT_LT(v0->l2_rate, 3.5);
  EXPECT_FALSE(v0->met);
  EXPECT_LT(v0->first_l2_rate, 0.0);
}

}  // namespace
