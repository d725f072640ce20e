// The check's verdict criteria, each failing alone on the exact sphere shell
// (patches 0-3, radii 0.5 and 1, poles degenerate and allowed) checked
// against icospheres: the message names the criterion, where and how much.
#include <gtest/gtest.h>

#include <cmath>

#include "check/check_models.h"
#include "igaprep/iga_check/report.h"

using namespace igaprep;
using namespace igaprep::iga_check;

namespace {

constexpr double kInner = 0.5, kOuter = 1.0;

std::vector<mesh::TriMesh> shell_surfaces() {
  return {check_test::icosphere(kOuter, 4), check_test::icosphere(kInner, 4)};
}

CheckReport check(const spline::MultiPatch& mp, const std::vector<mesh::TriMesh>& surfaces,
                  CheckOptions options = {}) {
  options.allow_degenerate = true;
  return build_check_report(mp, surfaces, {"outer", "inner"}, options, "shell");
}

const Criterion& criterion(const CheckReport& r, const std::string& name) {
  for (const Criterion& c : r.criteria)
    if (c.name == name) return c;
  throw std::runtime_error("no criterion " + name);
}

// Every criterion but `failing` passed; `failing` failed.
void expect_only_failure(const CheckReport& r, const std::string& failing) {
  EXPECT_FALSE(r.passed);
  ASSERT_EQ(r.criteria.size(), 5u);
  for (const Criterion& c : r.criteria) {
    EXPECT_TRUE(c.checked) << c.name;
    EXPECT_EQ(c.passed, c.name != failing) << c.name << ": " << c.summary;
  }
  EXPECT_EQ(r.verdict.rfind("FAIL: " + failing + ": ", 0), 0u) << r.verdict;
}

}  // namespace

TEST(Verdict, TheExactShellPassesEveryCriterion) {
  const CheckReport r = check(check_test::sphere_shell(kInner, kOuter), shell_surfaces());
  EXPECT_TRUE(r.passed) << r.verdict;
  EXPECT_EQ(r.verdict.rfind("PASS: all 8 elements of 4 patches certified", 0), 0u) << r.verdict;
  const Criterion& f = criterion(r, "fidelity");
  // The inscribed level-4 icosphere's chord error, over the diagonal 2 sqrt(3).
  EXPECT_GT(f.value, 1e-5);
  EXPECT_LT(f.value, 5e-4);
  const Criterion& v = criterion(r, "volume");
  EXPECT_GT(v.value, 0.0);  // the meshes enclose a little less than the spheres
  EXPECT_LT(v.value, 3e-3);
  EXPECT_DOUBLE_EQ(r.input_diagonal, mesh_diagonal(shell_surfaces()[0]));
}

TEST(Verdict, FidelityFailsAloneAndNamesTheUncoveredVertex) {
  const Eigen::Vector3d at = Eigen::Vector3d(1, 1, 0.3).normalized();
  auto surfaces = shell_surfaces();
  surfaces[0] = check_test::with_bump(surfaces[0], at, 0.05);  // 1.4 % of the diagonal, a sliver of volume
  const CheckReport r = check(check_test::sphere_shell(kInner, kOuter), surfaces);
  expect_only_failure(r, "fidelity");
  const Criterion& f = criterion(r, "fidelity");
  const double diag = mesh_diagonal(surfaces[0]);
  EXPECT_NEAR(f.value, 0.05 / diag, 2e-4);
  // The bump's vertex; the spline faces under the bump stay within the limit
  // of the bump's flanks.
  ASSERT_EQ(f.findings.size(), 1u) << f.summary;
  EXPECT_NE(f.findings[0].find("'outer': 1 input vertex around ("), std::string::npos) << f.findings[0];
  EXPECT_NE(f.findings[0].find("the farthest 1.4"), std::string::npos) << f.findings[0];

  // A looser limit accepts it.
  CheckOptions loose;
  loose.fidelity_limit = 0.02;
  EXPECT_TRUE(check(check_test::sphere_shell(kInner, kOuter), surfaces, loose).passed);
}

TEST(Verdict, SplineFacesAwayFromTheInputAreNamedByPatchAndSide) {
  // The model's outer sphere is 3 % larger than the input's: every outer face
  // lies 0.03 off it, 0.87 % of the diagonal (the volume fails as well).
  const CheckReport r = check(check_test::sphere_shell(kInner, 1.03 * kOuter), shell_surfaces());
  const Criterion& f = criterion(r, "fidelity");
  EXPECT_FALSE(f.passed);
  // The whole outer input is one uncovered region; 3 of the 4 faces named.
  ASSERT_EQ(f.findings.size(), 5u);
  EXPECT_NE(f.findings[0].find("'outer': 2562 input vertices around ("), std::string::npos) << f.findings[0];
  for (int i = 1; i <= 3; ++i) {
    EXPECT_NE(f.findings[i].find("'outer': patch "), std::string::npos) << f.findings[i];
    EXPECT_NE(f.findings[i].find(" side 6 (boundary) lies up to 0.8"), std::string::npos) << f.findings[i];
  }
  EXPECT_EQ(f.findings[4], "'outer': 1 more spline faces beyond the limit");
}

TEST(Verdict, VolumeFailsAloneWhenTheModelShrinksUniformly) {
  // Radii 0.4 % smaller: volume -1.2 % (-0.98 % against the inscribed meshes'
  // own deficit), distances 0.12 % of the diagonal.
  const double s = 0.996;
  const CheckReport r = check(check_test::sphere_shell(s * kInner, s * kOuter), shell_surfaces());
  expect_only_failure(r, "volume");
  const Criterion& v = criterion(r, "volume");
  EXPECT_NEAR(v.value, std::pow(s, 3) - 1.0, 3e-3);
  ASSERT_EQ(v.findings.size(), 1u);
  EXPECT_NE(v.findings[0].find("region 0 (inside 'outer'): 4 patches, volume"), std::string::npos) << v.findings[0];
  EXPECT_NE(r.verdict.find("volume: largest material volume difference -0.98"), std::string::npos) << r.verdict;
}

TEST(Verdict, ConformityFailsAloneForAGapAtAnInterface) {
  auto mp = check_test::sphere_shell(kInner, kOuter);
  spline::Patch& p = mp.patches[0];
  const int at = p.index(2, 2, 1);  // side u1 (the interface with patch 1), equator, outer radius
  p.control_points.row(at) *= 1.0 + 1e-4;
  const CheckReport r = check(mp, shell_surfaces());
  expect_only_failure(r, "conformity");
  const Criterion& c = criterion(r, "conformity");
  EXPECT_NEAR(c.value, 1e-4 / r.diagonal, 2e-5);
  ASSERT_FALSE(c.findings.empty());
}

TEST(Verdict, WatertightFailsAloneForASideListedTwice) {
  auto mp = check_test::sphere_shell(kInner, kOuter);
  mp.boundaries.push_back(mp.boundaries.front());
  const CheckReport r = check(mp, shell_surfaces());
  expect_only_failure(r, "watertight");
  const Criterion& w = criterion(r, "watertight");
  ASSERT_EQ(w.findings.size(), 1u);
  EXPECT_NE(w.findings[0].find("patch 0 side 5 is listed 2 times"), std::string::npos) << w.findings[0];
}

TEST(Verdict, JacobianFailsAloneWithoutDegenerateElementsAllowed) {
  CheckOptions strict;
  const CheckReport r =
      build_check_report(check_test::sphere_shell(kInner, kOuter), shell_surfaces(), {"outer", "inner"}, strict);
  expect_only_failure(r, "jacobian");
  EXPECT_EQ(r.verdict.rfind("FAIL: jacobian: patches 0 1 2 3 not certified positive (0 negative, 8 degenerate", 0), 0u)
      << r.verdict;
}

TEST(Verdict, AnInputSurfaceNoFaceStandsForFails) {
  // A third surface, well inside the void: no side carries its label.
  auto surfaces = shell_surfaces();
  surfaces.push_back(check_test::icosphere(0.2, 2));
  const CheckReport r = check(check_test::sphere_shell(kInner, kOuter), surfaces);
  const Criterion& f = criterion(r, "fidelity");
  EXPECT_FALSE(f.passed);
  ASSERT_FALSE(f.findings.empty());
  EXPECT_EQ(f.findings[0], "'surface 2': no spline face stands for it");
}

TEST(Verdict, PatchesInAVoidFailTheVolume) {
  // Two surfaces, one material: the inner sphere is a void. A model of the
  // whole ball (shell plus core) fills it.
  auto shell = check_test::sphere_shell(kInner, kOuter);
  const auto core = check_test::sphere_shell(0.1, kInner);
  for (const auto& p : core.patches) shell.patches.push_back(p);
  const CheckReport r = check(shell, shell_surfaces());
  const Criterion& v = criterion(r, "volume");
  EXPECT_FALSE(v.passed);
  ASSERT_FALSE(v.findings.empty());
  EXPECT_NE(v.findings[0].find("region 1 (inside 'inner') has no material, but 4 patches fill 99."), std::string::npos)
      << v.findings[0];
}

TEST(Verdict, WithoutSurfacesFidelityAndVolumeAreNotCheckedAndSaySo) {
  const CheckReport r = check(check_test::sphere_shell(kInner, kOuter), {});
  EXPECT_TRUE(r.passed) << r.verdict;
  EXPECT_FALSE(criterion(r, "fidelity").checked);
  EXPECT_FALSE(criterion(r, "volume").checked);
  EXPECT_NE(r.verdict.find("fidelity: not checked: no input surfaces"), std::string::npos) << r.verdict;
  ASSERT_EQ(r.warnings.size(), 2u);
  EXPECT_EQ(r.warnings[0], "fidelity not checked: no input surfaces");
}
