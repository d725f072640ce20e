// The inset capped where the solid is thin at M0trim's rim (param/rim_reach.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "igaprep/param/rim_reach.h"
#include "igaprep/param/surface_projector.h"
#include "param_meshes.h"

namespace {

using igaprep::param::rim_reach_cap;
using igaprep::param::SurfaceProjector;
using param_test::square_tris;

// The surface of the box [0, x1] x [0, 1] x [-h, h] (12 triangles, outward).
igaprep::mesh::TriMesh box_mesh(double x1, double h) {
  igaprep::mesh::TriMesh m;
  m.V.resize(8, 3);
  for (int i = 0; i < 8; ++i) m.V.row(i) << x1 * (i & 1), (i >> 1 & 1), (i & 4 ? h : -h);
  m.F.resize(12, 3);
  m.F << 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5;
  return m;
}

SurfaceProjector box_surface(double h) {
  const igaprep::mesh::TriMesh m = box_mesh(1.0, h);
  return SurfaceProjector(m.V, m.F);
}

// The square sheet's boundary, counter-clockwise.
std::vector<std::vector<int>> square_loop(int n) {
  std::vector<int> loop;
  auto id = [&](int i, int j) { return i + (n + 1) * j; };
  for (int i = 0; i < n; ++i) loop.push_back(id(i, 0));
  for (int j = 0; j < n; ++j) loop.push_back(id(n, j));
  for (int i = n; i > 0; --i) loop.push_back(id(i, n));
  for (int j = n; j > 0; --j) loop.push_back(id(0, j));
  return {loop};
}

// The midplane of a plate 0.02 thick with a flat rim: an inset of 0.15 would
// leave the rim to streamlines that cannot reach it; the cap is reach times
// the half-thickness (the sheet's (u, v) is its x, y, so 3D and (u, v)
// distances agree).
TEST(RimReach, AFlatThinRimCapsTheInsetAtReachHalfThicknesses) {
  const int n = 60;
  const igaprep::mesh::TriMesh sheet = square_tris(n);
  const Eigen::MatrixXd uv = sheet.V.leftCols(2);
  const auto r = rim_reach_cap(sheet, uv, square_loop(n), box_surface(0.01), 0.15, 2.0);
  EXPECT_NEAR(r.cap, 0.02, 1e-9);
  EXPECT_NEAR(r.half_thickness, 0.01, 1e-12);
  EXPECT_GT(r.considered, 1000);
  // Thin: the vertices within the inset but farther than 2 half-thicknesses
  // from the rim.
  int within = 0, thin = 0;
  for (Eigen::Index v = 0; v < sheet.V.rows(); ++v) {
    const double x = sheet.V(v, 0), y = sheet.V(v, 1);
    const double D = std::min({x, y, 1.0 - x, 1.0 - y});
    within += D > 0.0 && D < 0.15;
    thin += D > 0.02 + 1e-12 && D < 0.15;
  }
  EXPECT_EQ(r.considered, within);
  EXPECT_EQ(r.thin, thin);
  // Reach 4: twice the cap.
  EXPECT_NEAR(rim_reach_cap(sheet, uv, square_loop(n), box_surface(0.01), 0.15, 4.0).cap, 0.04, 1e-9);
}

// The same sheet in a solid as thick as it is wide near the rim (the box's
// walls are the nearest surface everywhere within the inset): no cap.
TEST(RimReach, AThickRimKeepsTheNominalInset) {
  const int n = 60;
  const igaprep::mesh::TriMesh sheet = square_tris(n);
  const Eigen::MatrixXd uv = sheet.V.leftCols(2);
  const auto r = rim_reach_cap(sheet, uv, square_loop(n), box_surface(5.0), 0.15, 2.0);
  EXPECT_EQ(r.cap, 0.15);
  EXPECT_EQ(r.thin, 0);
  EXPECT_GT(r.considered, 1000);
}

// A thin spot on a thick rim (a plate 0.02 thick over x < 0.1 only: a
// tenth of the vertices within the inset) does not shrink the whole inset.
TEST(RimReach, AThinSpotAloneKeepsTheNominalInset) {
  const int n = 60;
  const igaprep::mesh::TriMesh sheet = square_tris(n);
  const Eigen::MatrixXd uv = sheet.V.leftCols(2);
  // The rim: the thick box, and the thin slab as a second box whose top
  // lies 0.01 above the sheet where x < 0.1.
  const igaprep::mesh::TriMesh thick = box_mesh(1.0, 5.0), thin = box_mesh(0.1, 0.01);
  Eigen::MatrixXd V(16, 3);
  V << thick.V, thin.V;
  Eigen::MatrixXi F(24, 3);
  F << thick.F, thin.F.array() + 8;
  const auto r = rim_reach_cap(sheet, uv, square_loop(n), SurfaceProjector(V, F), 0.15, 2.0);
  EXPECT_GT(r.thin, 0);
  EXPECT_LT(r.thin, r.considered / 4);
  EXPECT_EQ(r.cap, 0.15);
}

}  // namespace
