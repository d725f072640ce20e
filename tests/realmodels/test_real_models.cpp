// Real meshes of ../shared/models run as a new user runs them: `igaprep run`
// on a case that names only the surface, every key at its default (issue
// 16). Each test asserts the exit code and the run's own figures
// (report.json) against the check's criteria.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/cli_runner.h"

namespace {

using nlohmann::json;

// The case a new user writes: the surface and nothing else.
std::string surface_only_case(const std::string& dir, const std::string& file) {
  const std::string path = dir + "/case.json";
  std::ofstream(path) << json{{"surfaces", {file}}}.dump();
  return path;
}

double figure(const json& report, const std::string& name) {
  const json& f = report.at("pipeline").at("figures");
  if (!f.contains(name)) {
    ADD_FAILURE() << "no figure " << name;
    return std::nan("");
  }
  return f.at(name).get<double>();
}

int count_lines(const std::string& text, const std::regex& line) {
  return static_cast<int>(std::distance(std::sregex_iterator(text.begin(), text.end(), line), std::sregex_iterator()));
}

// torus_genus3 (genus 3): 6 elements per direction leave one negative
// element and fidelity 0.830 %; the run fits it again at 9 and passes
// (2026-12-06: min scaled Jacobian 0.336, fidelity 0.402 %, volume
// -0.030 %, L2 rate 4.52; 248 s, 4.3 GB).
TEST(RealModels, TorusGenus3PassesWithDefaultKeys) {
  const std::string off = std::string(IGAPREP_SHARED_MODELS_DIR) + "/torus_genus3.off";
  if (!std::filesystem::exists(off)) GTEST_SKIP() << "shared model " << off << " is absent";
  const std::string dir = scratch_dir("torus_genus3");
  const CliResult r = run_cli("run " + surface_only_case(dir, off) + " -o " + dir + "/out");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const json report = json::parse(read_all(dir + "/out/report.json"));
  EXPECT_EQ(figure(report, "negative_elements"), 0.0);
  EXPECT_EQ(figure(report, "undecided_elements"), 0.0);
  EXPECT_EQ(figure(report, "degenerate_elements"), 0.0);
  EXPECT_GE(figure(report, "min_scaled_jacobian"), 0.3);
  EXPECT_LE(figure(report, "fidelity_relative_torus_genus3"), 0.005);
  EXPECT_LE(std::abs(figure(report, "volume_difference_region_0")), 0.005);
  EXPECT_EQ(figure(report, "unmatched_sides"), 0.0);
  EXPECT_EQ(figure(report, "interface_gap_relative"), 0.0);
  EXPECT_EQ(figure(report, "elements_per_direction"), 9.0) << "fitted again once, from 6";
  EXPECT_EQ(figure(report, "fit_attempts"), 2.0);
  const json& v = report.at("pipeline").at("validation");
  ASSERT_TRUE(v.at("ran").get<bool>());
  EXPECT_GE(v.at("l2_rate").get<double>(), 3.5);
  // The cut it chose: written, and described (4 loops for genus 3, and their corners).
  EXPECT_TRUE(std::filesystem::exists(dir + "/out/midsurface_loops.vtu"));
  EXPECT_EQ(count_lines(r.out, std::regex(R"(\n\s+loop [0-9]+: [0-9]+ vertices)")), 4) << r.out;
  EXPECT_EQ(count_lines(r.out, std::regex(R"(\n\s+corners of loop [0-9]+ \((hole|outer)\):)")), 4) << r.out;
  EXPECT_NE(r.out.find("retry "), std::string::npos) << "the run says why it fitted again";
}


// kitten.obj (genus 1), every key at its default but the validation (off to
// keep the test short): its ear was reached through too few samples
// (fidelity 1.439 %). The param stage halves the rectangles under the faces
// that miss it (11 -> 54), and where fidelity alone still fails (0.537 %,
// the samples too folded for a finer fit) the faces are fitted to the
// input. 2026-12-07: every element positive, min scaled Jacobian 0.240,
// fidelity 0.388 %, volume -0.028 %; 190 s.
TEST(RealModels, TheKittensCheckPassesWithDefaultKeys) {
  const std::string obj = std::string(IGAPREP_SHARED_MODELS_DIR) + "/kitten.obj";
  if (!std::filesystem::exists(obj)) GTEST_SKIP() << "shared model " << obj << " is absent";
  const std::string dir = scratch_dir("kitten");
  const std::string c = dir + "/case.json";
  std::ofstream(c) << json{{"surfaces", {obj}}, {"validation", {{"enabled", false}}}}.dump();
  const CliResult r = run_cli("run " + c + " -o " + dir + "/out");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const json report = json::parse(read_all(dir + "/out/report.json"));
  EXPECT_EQ(figure(report, "negative_elements"), 0.0);
  EXPECT_EQ(figure(report, "undecided_elements"), 0.0);
  EXPECT_GE(figure(report, "min_scaled_jacobian"), 0.2);
  EXPECT_LE(figure(report, "fidelity_relative_kitten"), 0.005);
  EXPECT_LE(std::abs(figure(report, "volume_difference_region_0")), 0.005);
  EXPECT_EQ(figure(report, "elements_per_direction"), 6.0);
  EXPECT_EQ(figure(report, "fit_attempts"), 2.0) << "the second with the faces fitted";
  EXPECT_NE(r.out.find("their rectangles halved"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("the faces on the input surfaces are fitted to them"), std::string::npos) << r.out;
}

// hand.obj (genus 0), the repair, the validation and the halved rectangles
// (decomposition.cover_rounds) off so that the test stays short (31 s):
// its blocks cover the hand, all five fingers (cut between its two sides,
// each finger an arm of the domain). It does not pass yet: negative
// elements from folded samples, and the wrist (2026-12-07: 1,014 negative
// without the repair, fidelity 1.21 %, volume -0.17 %; with every key at
// its default 197 negative, 1.207 %, -0.19 %, 293 s, before the halving;
// with the halving, the close sides merged and the last repair pass: 25
// negative of 170,640, fidelity 0.455 %, volume -0.044 %, 508 s; with the
// repair's rounds at the check's negative points 6 negative, 638 s; in
// docs/validation.md).
TEST(RealModels, TheHandsModelCoversItsFiveFingers) {
  const std::string obj = std::string(IGAPREP_SHARED_MODELS_DIR) + "/hand.obj";
  if (!std::filesystem::exists(obj)) GTEST_SKIP() << "shared model " << obj << " is absent";
  const std::string dir = scratch_dir("hand");
  const std::string c = dir + "/case.json";
  std::ofstream(c) << json{{"surfaces", {obj}},
                           {"validation", {{"enabled", false}}},
                           {"fit", {{"jacobian_target", 0}}},
                           {"decomposition", {{"cover_rounds", 0}}}}
                          .dump();
  const CliResult r = run_cli("run " + c + " -o " + dir + "/out");
  ASSERT_EQ(r.exit_code, 2) << r.out;  // built, and failed its check
  const json report = json::parse(read_all(dir + "/out/report.json"));
  EXPECT_LT(figure(report, "fidelity_relative_hand"), 0.015);  // 13.2 % with the palm plane
  EXPECT_LT(std::abs(figure(report, "volume_difference_region_0")), 0.005);  // -4.8 % with it
  EXPECT_NE(r.out.find("lobes of the outer loop: 5, each an arm of the domain"), std::string::npos) << r.out;
}

}  // namespace
