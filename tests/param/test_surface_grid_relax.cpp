// A block side's sample grid relaxed on T1 (param/surface_grid_relax.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <vector>

#include "igaprep/param/surface_grid_relax.h"
#include "igaprep/param/surface_projector.h"

namespace {

using igaprep::param::count_folded_on_surface;
using igaprep::param::relax_grid_on_surface;
using igaprep::param::SurfaceGridRelaxOptions;
using igaprep::param::SurfaceProjector;

// A roof z = -0.3 |x| over [-2, 2]^2: two planes meeting along the ridge
// x = 0, normals up.
SurfaceProjector roof() {
  Eigen::MatrixXd V(6, 3);
  V << -2, -2, -0.6, 0, -2, 0, 2, -2, -0.6, -2, 2, -0.6, 0, 2, 0, 2, 2, -0.6;
  Eigen::MatrixXi F(4, 3);
  F << 0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4;
  return SurfaceProjector(V, F);
}

double roof_z(double x) { return -0.3 * std::abs(x); }

// An m x m grid on the roof over [-1, 1]^2, first index fastest.
std::vector<Eigen::Vector3d> roof_grid(int m) {
  std::vector<Eigen::Vector3d> g;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const double x = -1.0 + 2.0 * i / (m - 1), y = -1.0 + 2.0 * j / (m - 1);
      g.emplace_back(x, y, roof_z(x));
    }
  return g;
}

// Three inner points pushed across their neighbours, as where a fan of
// streamline ends turns within a cell.
std::vector<Eigen::Vector3d> folded_roof_grid(int m) {
  std::vector<Eigen::Vector3d> g = roof_grid(m);
  auto push = [&](int i, int j, double dx, double dy) {
    Eigen::Vector3d& p = g[static_cast<std::size_t>(i + m * j)];
    p.x() += dx;
    p.y() += dy;
    p.z() = roof_z(p.x());
  };
  const double h = 2.0 / (m - 1);
  push(3, 3, 1.6 * h, 0.0);
  push(4, 3, -1.5 * h, 0.3 * h);
  push(5, 5, 0.2 * h, -1.7 * h);
  return g;
}

TEST(SurfaceGridRelax, FoldedCellsOnTheSurfaceAreUnfoldedWithTheBorderKept) {
  const SurfaceProjector surface = roof();
  const int m = 9;
  const std::vector<Eigen::Vector3d> g = folded_roof_grid(m);
  ASSERT_GE(count_folded_on_surface(g, m, surface), 4);
  EXPECT_EQ(count_folded_on_surface(roof_grid(m), m, surface), 0);

  const auto r = relax_grid_on_surface(g, m, surface);
  EXPECT_EQ(r.folded_before, count_folded_on_surface(g, m, surface));
  EXPECT_EQ(r.folded_after, 0);
  EXPECT_EQ(count_folded_on_surface(r.grid, m, surface), 0);
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const std::size_t q = static_cast<std::size_t>(i + m * j);
      const Eigen::Vector3d& p = r.grid[q];
      EXPECT_NEAR(p.z(), roof_z(p.x()), 1e-12) << "off the surface: " << i << ", " << j;
      if (i == 0 || j == 0 || i == m - 1 || j == m - 1) EXPECT_EQ(p, g[q]) << "border point moved: " << i << ", " << j;
    }
}

// Only the cells near the folds move (rings = 1): an uneven but unfolded
// part of the grid keeps its points bit for bit, as a face spread to follow
// a bulge of T1 keeps its denser samples there.
TEST(SurfaceGridRelax, PointsFarFromTheFoldsStayWhereTheyAre) {
  const SurfaceProjector surface = roof();
  const int m = 13;
  std::vector<Eigen::Vector3d> g = roof_grid(m);
  const double h = 2.0 / (m - 1);
  g[static_cast<std::size_t>(2 + m * 2)].x() += 1.5 * h;  // a fold near one corner
  g[static_cast<std::size_t>(2 + m * 2)].z() = roof_z(g[static_cast<std::size_t>(2 + m * 2)].x());
  g[static_cast<std::size_t>(10 + m * 10)].y() += 0.4 * h;  // uneven, not folded, far away
  ASSERT_GT(count_folded_on_surface(g, m, surface), 0);
  SurfaceGridRelaxOptions options;
  options.rings = 1;
  const auto r = relax_grid_on_surface(g, m, surface, options);
  EXPECT_EQ(r.folded_after, 0);
  for (int j = 5; j < m; ++j)
    for (int i = 5; i < m; ++i) EXPECT_EQ(r.grid[static_cast<std::size_t>(i + m * j)], g[static_cast<std::size_t>(i + m * j)]);
}

// A grid on the top of a slab whose columns crowd at its rim, the last on
// the slab's side: the mean of a point's neighbours next to the rim lies
// nearer the side than the top, and a point moved there would face away
// from its neighbours; every inner point stays on the top.
TEST(SurfaceGridRelax, NoPointCrossesToAPartFacingAway) {
  Eigen::MatrixXd V(8, 3);
  V << -1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0, -1, -1, 0.01, 1, -1, 0.01, 1, 1, 0.01, -1, 1, 0.01;
  Eigen::MatrixXi F(12, 3);
  F << 0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7;
  const SurfaceProjector slab(V, F);
  const int m = 7;
  const double xs[m] = {-1.0, -0.999, -0.995, -0.99, 0.5, 0.0, 1.0};  // columns 4 and 5 swapped: folded cells
  std::vector<Eigen::Vector3d> g;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) g.emplace_back(xs[i], -0.9 + 1.8 * j / (m - 1), i == 0 ? 0.0 : 0.01);
  SurfaceGridRelaxOptions options;
  options.rings = -1;
  options.rounds = 1;  // the first sweep is where the mean lies nearest the side
  const auto r = relax_grid_on_surface(g, m, slab, options);
  EXPECT_GT(r.folded_before, 0);
  for (int j = 1; j + 1 < m; ++j)
    for (int i = 1; i + 1 < m; ++i) EXPECT_DOUBLE_EQ(r.grid[static_cast<std::size_t>(i + m * j)].z(), 0.01) << i << ", " << j;
  for (int j = 1; j + 1 < m; ++j)  // the column next to the rim, whose moves were all refused
    EXPECT_EQ(r.grid[static_cast<std::size_t>(1 + m * j)], g[static_cast<std::size_t>(1 + m * j)]) << j;
}

}  // namespace
