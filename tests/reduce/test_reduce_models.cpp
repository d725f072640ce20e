// Data reduction of the built-in models fitted with 12 elements per
// direction, through a run with a "reduce" section: the bound holds what the
// samples measure, the reduced model stays certified and conforming, and
// `igaprep check` passes it.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "igaprep/pipeline/case.h"
#include "igaprep/pipeline/run.h"
#include "pipeline/pipeline_runs.h"

namespace {

using namespace igaprep;

double figure(const iga_check::PipelineSection& p, const std::string& name) {
  for (const auto& [key, value] : p.figures)
    if (key == name) return value;
  ADD_FAILURE() << "no figure " << name;
  return 0.0;
}

const char* const kReduce = R"({"reduce": {"relative_tolerance": 0.001}, "validation": {"enabled": false}})";

class ReducedBuiltInModel : public ::testing::TestWithParam<std::pair<std::string, std::string>> {};

TEST_P(ReducedBuiltInModel, StaysCertifiedConformingAndWithinItsBound) {
  const auto& [model, fit] = GetParam();
  nlohmann::json extra = nlohmann::json::parse(kReduce);
  extra["fit"] = nlohmann::json::parse(fit);
  const pipeline::Case c = pipeline_test::model_case(model, extra.dump(), "reduce_" + model);
  pipeline_test::Recorder observer;
  const pipeline::RunResult r = pipeline::run(c, observer);
  ASSERT_TRUE(r.report.pipeline.has_value());
  const iga_check::PipelineSection& p = *r.report.pipeline;

  const double asked = figure(p, "reduce_tolerance_asked"), tolerance = figure(p, "reduce_tolerance");
  const double bound = figure(p, "reduce_bound"), measured = figure(p, "reduce_measured_deviation");
  const double before = figure(p, "reduce_control_points_before"), after = figure(p, "control_points");
  std::printf("%s: control points %.0f -> %.0f (%.1f %%), tolerance %.4g (asked %.4g), bound %.4g, measured %.4g\n",
              model.c_str(), before, after, 100.0 * after / before, tolerance, asked, bound, measured);
  EXPECT_NEAR(asked, 1e-3 * r.report.diagonal, 1e-6 * r.report.diagonal);
  EXPECT_LE(tolerance, asked);
  EXPECT_LE(bound, tolerance);
  EXPECT_LE(measured, bound);
  EXPECT_GT(measured, 0.0);
  EXPECT_LT(after, before);
  // Certified and conforming, 1e-12 of the diagonal.
  EXPECT_TRUE(r.report.passed) << r.report.verdict;
  EXPECT_EQ(figure(p, "negative_elements"), 0.0);
  EXPECT_TRUE(r.report.topology.conforming);
  EXPECT_LE(r.report.topology.interface_max_gap_relative, 1e-12);

  // The written model passes `igaprep check` against the case's surfaces.
  const std::string dir = c.output_dir;
  {
    std::ofstream out(dir + "/case.json");
    out << pipeline::case_json(c, "");
  }
  const std::string command = std::string(IGAPREP_CLI) + " check " + dir + "/model.h5 --case " + dir +
                              "/case.json --report " + dir + "/check > " + dir + "/check.log 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
}

INSTANTIATE_TEST_SUITE_P(
    TwelveElements, ReducedBuiltInModel,
    ::testing::Values(std::make_pair(std::string("sphere2"), std::string(R"({"elements": 12, "jacobian_target": 0})")),
                      std::make_pair(std::string("ring2"), std::string(R"({"elements": 12})")),
                      std::make_pair(std::string("torus3"), std::string(R"({"elements": 12})"))),
    [](const auto& info) { return info.param.first; });

}  // namespace
