// The core's lids re-aimed where its ruled cells fold (param/lid_relax.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

#include "igaprep/param/lid_relax.h"

namespace {

using igaprep::param::count_folded_lid_cells;
using igaprep::param::LidRay;
using igaprep::param::lid_side_indices;
using igaprep::param::relax_lid_inside;
using igaprep::param::relax_lid_side;

constexpr double kLevel = 0.5;  // the lid's level: the plane z = 0.5 over a flat M at z = 0

// The ray to the plane z = kLevel; none when it runs parallel or away.
const LidRay to_level = [](const Eigen::Vector3d& from, const Eigen::Vector3d& dir) -> std::optional<Eigen::Vector3d> {
  if (!(dir.z() > 1e-12)) return std::nullopt;
  return from + (kLevel - from.z()) / dir.z() * dir;
};

// M: an m x m grid of [0, 1] x [y0, y0 + 1] at z = 0 (first index fastest).
std::vector<Eigen::Vector3d> flat_base(int m, double y0 = 0.0) {
  std::vector<Eigen::Vector3d> g;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) g.emplace_back(double(i) / (m - 1), y0 + double(j) / (m - 1), 0.0);
  return g;
}

// Rays up from M that lean towards x = 0.5 within a band |x - 0.5| < 0.15
// around it, as from a crease of M narrower than the core is thick: the
// rays of neighbouring columns cross before they reach the level.
std::vector<Eigen::Vector3d> crossing_lid(const std::vector<Eigen::Vector3d>& base) {
  std::vector<Eigen::Vector3d> lid;
  for (const Eigen::Vector3d& p : base) {
    const double d = p.x() - 0.5;
    const double lean = std::abs(d) < 0.15 ? -4.0 * d : 0.0;
    lid.push_back(*to_level(p, Eigen::Vector3d(lean, 0.0, 1.0).normalized()));
  }
  return lid;
}

// One rectangle as the param stage relaxes it: its four sides, then its
// inside. Returns the folded cells left.
int relax_rectangle(const std::vector<Eigen::Vector3d>& base, std::vector<Eigen::Vector3d>& lid, int m, const LidRay& ray) {
  for (int side = 0; side < 4; ++side) relax_lid_side(base, lid, lid_side_indices(m, side), ray);
  return relax_lid_inside(base, lid, m, ray);
}

TEST(RelaxLid, CrossingRaysAreReaimedUntilNoRuledCellFolds) {
  const int m = 17;
  const std::vector<Eigen::Vector3d> base = flat_base(m);
  std::vector<Eigen::Vector3d> lid = crossing_lid(base);
  const std::vector<Eigen::Vector3d> before = lid;
  const int folded = count_folded_lid_cells(base, lid, m);
  // The band holds 4 columns of rays; the 3 cells between them fold in all 16 rows.
  EXPECT_GE(folded, 16 * 3);
  EXPECT_EQ(relax_rectangle(base, lid, m, to_level), 0);
  EXPECT_EQ(count_folded_lid_cells(base, lid, m), 0);
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const std::size_t p = static_cast<std::size_t>(i + m * j);
      EXPECT_NEAR(lid[p].z(), kLevel, 1e-12) << "every lid point stays on the level";
      if ((i == 0 || i == m - 1) && (j == 0 || j == m - 1)) EXPECT_EQ(lid[p], before[p]) << "corners never move";
    }
  // Rows without folds keep their order and end evenly spread: x within
  // 1e-3 of the base's, as a discrete harmonic grid puts them.
  for (int i = 0; i < m; ++i) EXPECT_NEAR(lid[static_cast<std::size_t>(i + m * 8)].x(), double(i) / (m - 1), 1e-3);
}

TEST(RelaxLid, TwoRectanglesThatShareASideMoveItAlike) {
  const int m = 17;
  const std::vector<Eigen::Vector3d> below = flat_base(m, 0.0), above = flat_base(m, 1.0);
  std::vector<Eigen::Vector3d> lid_below = crossing_lid(below), lid_above = crossing_lid(above);
  relax_rectangle(below, lid_below, m, to_level);
  relax_rectangle(above, lid_above, m, to_level);
  for (int i = 0; i < m; ++i) {
    const std::size_t top_row = static_cast<std::size_t>(i + m * (m - 1)), bottom_row = static_cast<std::size_t>(i);
    EXPECT_EQ(lid_below[top_row], lid_above[bottom_row]) << "point " << i << " of the shared side";
  }
  EXPECT_EQ(count_folded_lid_cells(below, lid_below, m), 0);
  EXPECT_EQ(count_folded_lid_cells(above, lid_above, m), 0);
}

TEST(RelaxLid, ALidWithoutFoldsIsLeftAsItIs) {
  const int m = 9;
  const std::vector<Eigen::Vector3d> base = flat_base(m);
  std::vector<Eigen::Vector3d> lid;
  for (const Eigen::Vector3d& p : base) lid.push_back(*to_level(p, Eigen::Vector3d(0.2 * p.x(), 0.1, 1.0).normalized()));
  const std::vector<Eigen::Vector3d> before = lid;
  EXPECT_EQ(count_folded_lid_cells(base, lid, m), 0);
  EXPECT_EQ(relax_rectangle(base, lid, m, to_level), 0);
  EXPECT_EQ(lid, before);
}

TEST(RelaxLid, APointWhoseRayFailsStaysWhereItWas) {
  const int m = 9;
  const std::vector<Eigen::Vector3d> base = flat_base(m);
  std::vector<Eigen::Vector3d> lid = crossing_lid(base);
  const std::vector<Eigen::Vector3d> before = lid;
  const LidRay fails = [](const Eigen::Vector3d&, const Eigen::Vector3d&) { return std::optional<Eigen::Vector3d>(); };
  const int folded = count_folded_lid_cells(base, lid, m);
  EXPECT_GT(folded, 0);
  EXPECT_EQ(relax_rectangle(base, lid, m, fails), folded);
  EXPECT_EQ(lid, before);
}

}  // namespace
