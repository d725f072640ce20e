// The check report: verdict and failed patches, report.html is one
// self-contained file with SVG histograms, report.json has every key that
// docs/check-report.md documents, with the documented type.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "check/check_models.h"
#include "igaprep/iga_check/report.h"
#include "igaprep/spline/bezier_extraction.h"
#include "igaprep/spline/refine.h"

using namespace igaprep;
using namespace igaprep::iga_check;

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct DocKey {
  std::string path, type;
};

std::vector<DocKey> documented_keys() {
  std::ifstream in(std::string(IGAPREP_SOURCE_DIR) + "/docs/check-report.md");
  std::vector<DocKey> keys;
  std::string line;
  const std::regex row(R"(^\| `([^`]+)` \| ([a-z ]+) \|)");
  std::smatch m;
  while (std::getline(in, line))
    if (std::regex_search(line, m, row)) keys.push_back({m[1], m[2]});
  return keys;
}

bool has_type(const nlohmann::json& v, const std::string& type) {
  if (type == "string") return v.is_string();
  if (type == "integer") return v.is_number_integer();
  if (type == "number") return v.is_number();
  if (type == "number or null") return v.is_number() || v.is_null();
  if (type == "boolean") return v.is_boolean();
  if (type == "array") return v.is_array();
  if (type == "object") return v.is_object();
  ADD_FAILURE() << "unknown documented type " << type;
  return false;
}

// Checks `path` (segments separated by '.', "name[]" = every element of the
// array) in j; counts the values checked.
void check_path(const nlohmann::json& j, const std::vector<std::string>& seg, size_t i, const DocKey& key, int* seen) {
  if (i == seg.size()) {
    ++*seen;
    EXPECT_TRUE(has_type(j, key.type)) << key.path << " should be " << key.type << ", is " << j.dump().substr(0, 80);
    return;
  }
  std::string s = seg[i];
  const bool each = s.size() > 2 && s.substr(s.size() - 2) == "[]";
  if (each) s = s.substr(0, s.size() - 2);
  ASSERT_TRUE(j.is_object()) << key.path;
  ASSERT_TRUE(j.contains(s)) << "report.json lacks documented key " << key.path;
  if (!each) return check_path(j.at(s), seg, i + 1, key, seen);
  ASSERT_TRUE(j.at(s).is_array()) << key.path;
  for (const auto& e : j.at(s)) check_path(e, seg, i + 1, key, seen);
}

}  // namespace

TEST(CheckReport, SphereShellReportFilesAndDocumentedKeys) {
  const auto mp = check_test::sphere_shell(0.5, 1.0);
  // Level 4: the inscribed meshes' volume within 0.5 % of the spheres' (level 3: 0.87 %).
  const std::vector<mesh::TriMesh> surfaces = {check_test::icosphere(1.0, 4), check_test::icosphere(0.5, 4)};
  CheckOptions opt;
  const CheckReport strict = build_check_report(mp, surfaces, {"outer", "inner"}, opt, "sphere_shell");
  EXPECT_FALSE(strict.passed);  // the poles make degenerate elements
  EXPECT_EQ(strict.failed_patches, (std::vector<int>{0, 1, 2, 3}));
  // The verdict says what would pass, in the library's terms (no command-line option).
  EXPECT_NE(strict.verdict.find("only degenerate elements fail"), std::string::npos) << strict.verdict;
  EXPECT_EQ(strict.verdict.find("--"), std::string::npos) << strict.verdict;
  opt.allow_degenerate = true;
  CheckReport r = build_check_report(mp, surfaces, {"outer", "inner"}, opt, "sphere_shell");
  EXPECT_TRUE(r.passed) << r.verdict;
  r.generator = "igaprep test";
  r.date = "2026-12-03T07:00:00Z";
  EXPECT_EQ(r.verdict.rfind("PASS", 0), 0u);

  const std::string dir = std::string(IGAPREP_BINARY_DIR) + "/test_check_report";
  std::filesystem::remove_all(dir);
  write_report(r, dir);
  const std::string html = slurp(dir + "/report.html");
  ASSERT_FALSE(html.empty());
  EXPECT_EQ(html.find("src="), std::string::npos);
  EXPECT_EQ(html.find("href="), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  EXPECT_EQ(html.find("@import"), std::string::npos);
  EXPECT_EQ(html.find("url("), std::string::npos);
  size_t svgs = 0;
  for (size_t at = html.find("<svg"); at != std::string::npos; at = html.find("<svg", at + 1)) ++svgs;
  EXPECT_EQ(svgs, 5u);  // the model's three pictures and two histograms
  // Issue 23, item 3: the model drawn in the report, one polygon per element
  // face on a labelled side.
  EXPECT_NE(html.find("<svg id=\"model-picture\""), std::string::npos);
  std::size_t faces = 0;
  for (const auto& b : mp.boundaries) {
    const auto& p = mp.patches[static_cast<std::size_t>(b.patch)];
    const int n = b.side.direction();
    std::size_t count = 1;
    for (int d = 0; d < 3; ++d)
      if (d != n) count *= static_cast<std::size_t>(igaprep::spline::bezier_extraction(p).element_count(d));
    faces += count;
  }
  std::size_t polygons = 0;
  for (size_t at = html.find("<polygon"); at != std::string::npos; at = html.find("<polygon", at + 1)) ++polygons;
  EXPECT_EQ(polygons, 3 * faces);  // by quality, by patch, by material
  EXPECT_GT(faces, 0u);
  // The worst elements marked on the quality picture, numbered as in their table.
  std::size_t marks = 0;
  for (size_t at = html.find("class=\"mark\""); at != std::string::npos; at = html.find("class=\"mark\"", at + 1)) ++marks;
  EXPECT_EQ(marks, std::min<std::size_t>(5, r.worst_elements.size()));
  EXPECT_GT(marks, 0u);
  // Version and date (issue 23, item 3), and how to view the model.
  EXPECT_NE(html.find("Made by igaprep test on 2026-12-03T07:00:00Z."), std::string::npos);
  EXPECT_NE(html.find("Nonlinear Subdivision Level"), std::string::npos);
  EXPECT_NE(html.find("scaled Jacobian"), std::string::npos);
  // Log-scale bars, and the threshold 0 marked on the scaled Jacobian's
  // range [-1, 1] (issue 23, item 3).
  EXPECT_NE(html.find("log scale"), std::string::npos);
  EXPECT_NE(html.find("class=\"threshold\""), std::string::npos);
  EXPECT_NE(html.find(r.verdict), std::string::npos);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator{}), 2);

  const nlohmann::json j = nlohmann::json::parse(slurp(dir + "/report.json"));
  const auto keys = documented_keys();
  ASSERT_GT(keys.size(), 100u);
  for (const DocKey& k : keys) {
    std::vector<std::string> seg;
    std::stringstream ss(k.path);
    for (std::string s; std::getline(ss, s, '.');) seg.push_back(s);
    int seen = 0;
    check_path(j, seg, 0, k, &seen);
    EXPECT_GT(seen, 0) << "documented key " << k.path << " has no value to check in this report";
  }
  // Values, not only types.
  EXPECT_EQ(j["summary"]["elements"], 4 * 2);
  EXPECT_EQ(j["summary"]["degenerate"], 8);
  EXPECT_EQ(j["topology"]["collapsed_sides"].size(), 8u);
  EXPECT_EQ(j["fidelity"].size(), 2u);
  EXPECT_EQ(j["topology"]["regions"][1]["patches"], 0);
  EXPECT_TRUE(j["summary"]["passed"].get<bool>());
  long total = 0;
  for (long c : j["quality"]["scaled_jacobian"]["histogram"]["counts"]) total += c;
  EXPECT_EQ(total, j["quality"]["scaled_jacobian"]["count"].get<long>());
  // Same input, byte-identical output.
  CheckReport again = build_check_report(mp, surfaces, {"outer", "inner"}, opt, "sphere_shell");
  again.generator = r.generator;
  again.date = r.date;
  EXPECT_EQ(report_json(again), report_json(r));
}

TEST(CheckReport, FoldedModelFailsAndNamesThePatch) {
  auto fold = [](const Eigen::Vector3d& t) { return Eigen::Vector3d(t[0] + 3.0 * t[0] * (1 - t[0]) * t[1], t[1], t[2]); };
  auto box = [](const Eigen::Vector3d& t) { return Eigen::Vector3d(t[0] + 2, t[1], t[2]); };
  spline::MultiPatch mp = check_test::single(check_test::bezier_patch(box, {{2, 2, 2}}));
  mp.patches.push_back(spline::refine_uniformly(check_test::bezier_patch(fold, {{2, 2, 2}}), 1));
  const CheckReport r = build_check_report(mp, {}, {}, {}, "fold");
  EXPECT_FALSE(r.passed);
  EXPECT_EQ(r.failed_patches, std::vector<int>{1});
  EXPECT_EQ(r.verdict.rfind("FAIL: jacobian: patches 1 ", 0), 0u) << r.verdict;
  EXPECT_NE(r.verdict.find("; watertight: "), std::string::npos) << r.verdict;
  ASSERT_FALSE(r.worst_elements.empty());
  EXPECT_EQ(r.worst_elements[0].status, ElementStatus::Negative);
  EXPECT_EQ(r.worst_elements[0].patch, 1);
  EXPECT_TRUE(r.patches[0].passed);
  EXPECT_EQ(r.patches[1].negative, 4);
  EXPECT_FALSE(r.topology.watertight);  // patch 1 has no sides listed
  EXPECT_FALSE(r.warnings.empty());
}
