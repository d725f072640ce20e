// Multipatch: interface correspondence in a non-trivial orientation,
// conformity check that names the faulty interface, global numbering.
#include <gtest/gtest.h>

#include "igaprep/core/error.h"
#include "spline_test_util.h"

using namespace spline_test;

namespace {
// Patch 0: a distorted box. Patch 1 glued to its u1 face with its own w0 face;
// a's v runs along b's u reversed, a's w along b's v in the same sense.
MultiPatch two_patches(std::mt19937& rng) {
  MultiPatch mp;
  Patch A = random_patch(rng, {{2, 2, 1}}, {{4, 5, 3}}, true, 1);
  Patch B;
  B.degrees = {{A.degrees[1], A.degrees[2], 2}};
  std::vector<double> ku(A.knots[1].size());
  for (size_t k = 0; k < ku.size(); ++k) ku[k] = 1.0 - A.knots[1][ku.size() - 1 - k];
  B.knots = {{ku, A.knots[2], {0, 0, 0, 0.5, 1, 1, 1}}};
  const int n0 = B.count(0), n1 = B.count(1), n2 = B.count(2);
  B.control_points.resize(n0 * n1 * n2, 3);
  B.weights.resize(n0 * n1 * n2);
  std::uniform_real_distribution<double> J(-0.05, 0.05);
  for (int k = 0; k < n2; ++k)
    for (int j = 0; j < n1; ++j)
      for (int i = 0; i < n0; ++i) {
        const int a = A.index(A.count(0) - 1, A.count(1) - 1 - i, j);
        Eigen::RowVector3d x = A.control_points.row(a) + Eigen::RowVector3d(0.4 * k, 0, 0);
        if (k > 0) x += Eigen::RowVector3d(J(rng), J(rng), J(rng));
        B.control_points.row(B.index(i, j, k)) = x;
        B.weights[B.index(i, j, k)] = k == 0 ? A.weights[a] : 1.0 + 0.1 * k;
      }
  mp.patches = {A, B};
  Interface itf;
  itf.patch_a = 0, itf.side_a = kU1, itf.patch_b = 1, itf.side_b = kW0;
  itf.dirmap = {{2, 0, 1}};
  itf.orient = {{1, 0, 1}};
  mp.interfaces = {itf};
  mp.labels = {"outer"};
  mp.materials = {Material{"steel", 210e9, 0.3}};
  return mp;
}
}  // namespace

TEST(SplineMultipatch, ConformingInterfaceIsGeometricallyContinuous) {
  std::mt19937 rng(31);
  const MultiPatch mp = two_patches(rng);
  validate_multipatch(mp);
  const ConformityReport rep = check_conformity(mp, 1e-12);
  EXPECT_TRUE(rep.conforming) << (rep.problems.empty() ? "" : rep.problems[0]);
  EXPECT_LT(rep.max_deviation, 1e-15);
  // The two faces are the same surface under the parameter map.
  std::uniform_real_distribution<double> R(0, 1);
  for (int s = 0; s < 200; ++s) {
    const double v = R(rng), w = R(rng);
    const Eigen::Vector3d xa = evaluate_point(mp.patches[0], {1.0, v, w});
    const Eigen::Vector3d xb = evaluate_point(mp.patches[1], {1.0 - v, w, 0.0});
    EXPECT_LT((xa - xb).norm(), 1e-13);
  }
}

TEST(SplineMultipatch, GlobalNumberingCountsSharedPointsOnce) {
  std::mt19937 rng(32);
  const MultiPatch mp = two_patches(rng);
  const GlobalNumbering g = global_numbering(mp);
  const int na = static_cast<int>(mp.patches[0].control_points.rows());
  const int nb = static_cast<int>(mp.patches[1].control_points.rows());
  const int face = mp.patches[0].count(1) * mp.patches[0].count(2);
  EXPECT_EQ(g.count, na + nb - face);
  // Coincident points get the same number, and only they do.
  std::vector<int> uses(g.count, 0);
  for (int p = 0; p < 2; ++p)
    for (int i = 0; i < static_cast<int>(g.global[p].size()); ++i) ++uses[g.global[p][i]];
  int shared = 0;
  for (int u : uses) {
    EXPECT_GE(u, 1);
    EXPECT_LE(u, 2);
    shared += (u == 2);
  }
  EXPECT_EQ(shared, face);
  for (const auto& pr : interface_point_pairs(mp, mp.interfaces[0])) {
    EXPECT_EQ(g.global[0][pr.first], g.global[1][pr.second]);
    EXPECT_LT((mp.patches[0].control_points.row(pr.first) - mp.patches[1].control_points.row(pr.second)).norm(), 1e-15);
  }
  EXPECT_EQ(g.patch_offset[1], na);
}

TEST(SplineMultipatch, ConformityCheckNamesShiftedInterfacePoint) {
  std::mt19937 rng(33);
  MultiPatch mp = two_patches(rng);
  const auto pairs = interface_point_pairs(mp, mp.interfaces[0]);
  const int b = pairs[7].second;
  mp.patches[1].control_points(b, 1) += 1.2e-3;
  const ConformityReport rep = check_conformity(mp, 1e-6);
  ASSERT_FALSE(rep.conforming);
  ASSERT_EQ(rep.problems.size(), 1u);
  EXPECT_NE(rep.problems[0].find("interface 0 (patch 0 side 2 / patch 1 side 5)"), std::string::npos) << rep.problems[0];
  EXPECT_NE(rep.problems[0].find("control point " + std::to_string(pairs[7].first) + " / " + std::to_string(b)),
            std::string::npos)
      << rep.problems[0];
  EXPECT_NE(rep.problems[0].find("off by 1.2e-03"), std::string::npos) << rep.problems[0];
  EXPECT_NEAR(rep.max_deviation, 1.2e-3, 1e-12);
}

TEST(SplineMultipatch, MismatchedKnotsAndBadInterfacesAreReported) {
  std::mt19937 rng(34);
  MultiPatch mp = two_patches(rng);
  mp.patches[1].knots[1][2] += 0.01;  // interior knot of b's v (= a's w)
  if (mp.patches[1].knots[1].size() <= 5) {
    // a's w has no interior knot in this set-up; disturb b's u instead.
    mp.patches[1].knots[1][2] -= 0.01;
    mp.patches[1].knots[0][3] += 0.01;
  }
  ConformityReport rep = check_conformity(mp, 1e-6);
  ASSERT_FALSE(rep.conforming);
  EXPECT_NE(rep.problems[0].find("knot vectors differ after orientation"), std::string::npos) << rep.problems[0];
  mp = two_patches(rng);
  mp.interfaces[0].dirmap = {{0, 1, 2}};
  EXPECT_THROW(validate_multipatch(mp), igaprep::Error);
  rep = check_conformity(mp, 1e-6);
  ASSERT_FALSE(rep.conforming);
  EXPECT_NE(rep.problems[0].find("interface 0"), std::string::npos);
}
