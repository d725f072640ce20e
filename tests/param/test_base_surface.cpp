// The base surface M = {b >= m0} (seed paper, sections 4.3 and 4.4).
#include <gtest/gtest.h>

#include "igaprep/core/error.h"
#include "igaprep/param/sheet_topology.h"
#include "test_midsurface_cache.h"

using namespace igaprep::param;
using midsurface_test::cached;
using midsurface_test::kVariants;
using midsurface_test::Variant;
using midsurface_test::variant_name;

namespace {
class Base : public ::testing::TestWithParam<Variant> {};

double area(const igaprep::mesh::TriMesh& m) {
  double a = 0.0;
  for (int f = 0; f < m.F.rows(); ++f) {
    const Eigen::Vector3d p = m.V.row(m.F(f, 0)), q = m.V.row(m.F(f, 1)), s = m.V.row(m.F(f, 2));
    a += 0.5 * (q - p).cross(s - p).norm();
  }
  return a;
}
}  // namespace

TEST_P(Base, SingleSheetStrictlyInsideWithCornersOnItsBoundary) {
  const auto& c = cached(GetParam().model, GetParam().variant);
  const auto& r = c.result;
  const BaseSurface& M = r.base;
  const int g = GetParam().genus;
  const SheetTopology t = analyze_sheet(M.mesh.F, M.mesh.V.rows());
  EXPECT_EQ(describe_sheet_problem(t, g + 1, "M"), "");
  EXPECT_FALSE(M.medial.empty());
  // Strictly inside Tn: positive distance and inside.
  const auto& Tn = c.model.surfaces.back();
  double dmin = 1e300;
  for (Eigen::Index i = 0; i < M.mesh.V.rows(); i += 3) {
    const Eigen::Vector3d p = M.mesh.V.row(i);
    dmin = std::min(dmin, midsurface_test::distance_to_surface(p, Tn));
    EXPECT_GT(midsurface_test::winding_number(p, Tn), 0.5) << "vertex " << i;
  }
  EXPECT_GT(dmin, 1e-4 * c.diag);
  // (u, v) inherited: positively oriented.
  for (int f = 0; f < M.mesh.F.rows(); ++f) {
    const Eigen::Vector2d a = M.uv.row(M.mesh.F(f, 0)), b = M.uv.row(M.mesh.F(f, 1)), q = M.uv.row(M.mesh.F(f, 2));
    EXPECT_GT((b - a)(0) * (q - a)(1) - (q - a)(0) * (b - a)(1), 0.0) << "face " << f;
  }
  // Corners: four distinct per loop, all on M's boundary loop of that loop, near the grad-b trace ends.
  ASSERT_EQ(static_cast<int>(M.corners.size()), g + 1);
  for (std::size_t l = 0; l < M.corners.size(); ++l) {
    const auto& loop = t.boundary_loops.at(static_cast<std::size_t>(M.corner_loop[l]));
    for (int k = 0; k < 4; ++k) {
      const int v = M.corners[l][k];
      EXPECT_NE(std::find(loop.begin(), loop.end(), v), loop.end()) << "corner " << l << "." << k;
      const Eigen::Vector3d end = M.corner_traces_end.row(static_cast<Eigen::Index>(4 * l + k));
      EXPECT_LT((M.mesh.V.row(v).transpose() - end).norm(), 0.1 * c.diag);
    }
  }
}

TEST_P(Base, LargerM0GivesSmallerM) {
  const auto& r = cached(GetParam().model, GetParam().variant).result;
  const auto& S = r.m0trim.mesh;
  const double a3 = area(r.base.mesh);
  const BaseSurface M5 = base_surface(S, r.polycube, 0.5, GetParam().genus + 1);
  const BaseSurface M1 = base_surface(S, r.polycube, 0.1, GetParam().genus + 1);
  EXPECT_LT(area(M5.mesh), a3);
  EXPECT_LT(a3, area(M1.mesh));
  EXPECT_LT(area(M1.mesh), area(S));
  // b within [0, 1] up to the cotangent Laplacian's maximum-principle
  // violations on obtuse triangles (up to 2 % measured on torus3's M0trim).
  EXPECT_GE(M5.b.minCoeff(), -0.05);
  EXPECT_LE(M5.b.maxCoeff(), 1.05);
}

// Automatic cuts on every genus, and sphere2 cut by a plane and by explicit loops.
INSTANTIATE_TEST_SUITE_P(Models, Base,
                         ::testing::ValuesIn(kVariants), variant_name);

TEST(BaseSurfaceRefusal, M0OutsideTheOpenInterval) {
  const auto& r = cached("sphere2").result;
  EXPECT_THROW(trim_base_surface(r.m0trim.mesh, r.base.b, 1.0, r.polycube.uv), igaprep::Error);
  EXPECT_THROW(trim_base_surface(r.m0trim.mesh, r.base.b, 0.0, r.polycube.uv), igaprep::Error);
}
