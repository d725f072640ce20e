// The midsurface M0 and M0trim (seed paper, sections 4.1 and 4.2) on the
// built-in models with automatic cuts, and on sphere2 with a plane and with
// explicit loops.
#include <cmath>

#include <gtest/gtest.h>

#include "igaprep/core/error.h"
#include "igaprep/param/sheet_topology.h"
#include "test_midsurface_cache.h"

using namespace igaprep;
using namespace igaprep::param;
using midsurface_test::cached;
using midsurface_test::kVariants;
using midsurface_test::Variant;
using midsurface_test::variant_name;

namespace {



class MidsurfaceModels : public ::testing::TestWithParam<Variant> {};

}  // namespace

TEST_P(MidsurfaceModels, LoopsAndM0BoundaryOnT1) {
  const Variant& v = GetParam();
  const auto& c = cached(v.model, v.variant);
  const auto& r = c.result;
  EXPECT_EQ(r.cut.genus, v.genus);
  EXPECT_EQ(static_cast<int>(r.cut.loops.size()), v.genus + 1);
  // M0 is one sheet with g + 1 boundary loops ...
  const SheetTopology t = analyze_sheet(r.m0.mesh.F, r.m0.mesh.V.rows());
  EXPECT_EQ(describe_sheet_problem(t, v.genus + 1, "M0"), "");
  // ... whose boundary lies on T1 (the original surface) within 1e-9 of the diagonal,
  // and every vertex lies inside T1.
  double worst = 0.0;
  int boundary_vertices = 0;
  for (const auto& loop : t.boundary_loops)
    for (int i : loop) {
      worst = std::max(worst, midsurface_test::distance_to_surface(r.m0.mesh.V.row(i), c.model.surfaces[0]));
      ++boundary_vertices;
    }
  EXPECT_LE(worst, 1e-9 * c.diag);
  int loop_vertices = 0;
  for (const auto& l : r.cut.loops) loop_vertices += static_cast<int>(l.size());
  EXPECT_EQ(boundary_vertices, loop_vertices) << "M0's boundary is exactly the cut loops";
  for (Eigen::Index i = 0; i < r.m0.mesh.V.rows(); i += 7) {
    const Eigen::Vector3d p = r.m0.mesh.V.row(i);
    const bool on = midsurface_test::distance_to_surface(p, c.model.surfaces[0]) <= 1e-9 * c.diag;
    EXPECT_TRUE(on || midsurface_test::winding_number(p, c.model.surfaces[0]) > 0.5) << "vertex " << i;
  }
  // f is +1 / -1 on R+ / R- and within [-1, 1].
  EXPECT_LE(r.f.maxCoeff(), 1.0 + 1e-12);
  EXPECT_GE(r.f.minCoeff(), -1.0 - 1e-12);
}

TEST_P(MidsurfaceModels, M0trimIsOneSheetInsideTheInnermostSurface) {
  const Variant& v = GetParam();
  const auto& c = cached(v.model, v.variant);
  const auto& r = c.result;
  const SheetTopology t = analyze_sheet(r.m0trim.mesh.F, r.m0trim.mesh.V.rows());
  EXPECT_EQ(describe_sheet_problem(t, v.genus + 1, "M0trim"), "");
  const auto& Tn = c.model.surfaces.back();
  if (c.model.surfaces.size() == 1) {
    // M0trim = M0 for one surface (refined only at ears and hole corners)
    EXPECT_GE(r.m0trim.mesh.F.rows(), r.m0.mesh.F.rows());
    EXPECT_EQ((r.m0trim.m0_vertex.array() >= 0).count(), r.m0.mesh.V.rows());
  } else {
    EXPECT_LT(r.m0trim.mesh.F.rows(), r.m0.mesh.F.rows());
    // the boundary on Tn, every vertex inside or on it
    for (const auto& loop : t.boundary_loops)
      for (int i : loop) EXPECT_LE(midsurface_test::distance_to_surface(r.m0trim.mesh.V.row(i), Tn), 1e-9 * c.diag);
    for (Eigen::Index i = 0; i < r.m0trim.mesh.V.rows(); i += 5) {
      const Eigen::Vector3d p = r.m0trim.mesh.V.row(i);
      const bool inside = midsurface_test::winding_number(p, Tn) > 0.5;
      EXPECT_TRUE(inside || midsurface_test::distance_to_surface(p, Tn) <= 1e-9 * c.diag) << "vertex " << i;
    }
  }
}

TEST_P(MidsurfaceModels, PathLengthVarianceIsReported) {
  const auto& r = cached(GetParam().model, GetParam().variant).result;
  EXPECT_GT(r.paths.traced, 0);
  EXPECT_GE(r.paths.reached, static_cast<int>(0.99 * r.paths.traced));
  EXPECT_GT(r.paths.mean, 0.0);
  EXPECT_GE(r.paths.variance, 0.0);
  EXPECT_LE(r.paths.min, r.paths.mean);
  EXPECT_GE(r.paths.max, r.paths.mean);
  EXPECT_LE(r.paths.variance, (r.paths.max - r.paths.min) * (r.paths.max - r.paths.min));
}

INSTANTIATE_TEST_SUITE_P(Models, MidsurfaceModels, ::testing::ValuesIn(kVariants), variant_name);

TEST(MidsurfaceRefusal, PlaneAcrossTheTubeGivesTwoSheets) {
  // Plane x = 0 through ring2: two loops (right count), two connected regions,
  // but M0 is two discs: refused with the reason.
  const auto model = models::make_builtin_model("ring2");
  MidsurfaceOptions o;
  o.cut = MidsurfaceOptions::CutKind::Plane;
  o.plane.point = Eigen::Vector3d(0.0, 0.013, 0.0);
  o.plane.normal = Eigen::Vector3d::UnitY();
  o.path_lengths = false;
  try {
    build_midsurface(model.surfaces, o, "ring2 outer");
    FAIL() << "expected a refusal";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    EXPECT_NE(std::string(e.what()).find("2 separate pieces"), std::string::npos) << e.what();
  }
}

namespace {

// One tet, its four vertices at the corners of the unit simplex.
mesh::TetMesh unit_tet() {
  mesh::TetMesh tets;
  tets.V.resize(4, 3);
  tets.V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  tets.T.resize(1, 4);
  tets.T << 0, 1, 2, 3;
  return tets;
}

TEST(MidsurfaceRefusal, ATetWithFourVerticesOnTheLoopsIsBadInputNamingIt) {
  const mesh::TetMesh tets = unit_tet();
  const Eigen::VectorXd f = Eigen::VectorXd::Zero(4);
  try {
    zero_sheet(tets, f, 4, 0.0);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    EXPECT_NE(std::string(e.what()).find("all four vertices of tet 0 (near (0.25, 0.25, 0.25)) are at f = 0"),
              std::string::npos)
        << e.what();
  }
}

// The same tet through extract_midsurface (with and without snapping): the
// message keeps the reason and names the case keys that change it.
TEST(MidsurfaceRefusal, ATetAtFZeroNamesTheCaseKeysThatChangeIt) {
  const mesh::TetMesh tets = unit_tet();
  CutLoops cut;
  cut.surface.V = tets.V;
  cut.surface.F.resize(4, 3);
  cut.surface.F << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3;
  cut.source = "a test's loops";
  try {
    extract_midsurface(tets, cut, Eigen::VectorXd::Zero(4), 0.05);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    const std::string m = e.what();
    EXPECT_NE(m.find("all four vertices of tet 0"), std::string::npos) << m;
    EXPECT_NE(m.find("(cut: a test's loops)"), std::string::npos) << m;
    EXPECT_NE(m.find("'midsurface.cut'"), std::string::npos) << m;
    EXPECT_NE(m.find("'tetmesh.max_volume'"), std::string::npos) << m;
  }
}


// A loop edge (0, 1) on T1 with its fan of four tets from the face on R+'s
// side (vertex 2, f = 1) to the face on R-'s (vertex 3, f = -1). The free
// vertices between go +, -, +: a discrete harmonic f need not be monotone
// there (the hand's thin sides, 2026-12-07), and the edge would bound three
// triangles of M0. The vertex that breaks the order at the least |f| (the
// last, 0.02) changes sign: the edge bounds one triangle.
TEST(MidsurfaceLoopEdge, ASignOutOfOrderRoundALoopEdgeIsSettled) {
  mesh::TetMesh tets;
  tets.V.resize(7, 3);
  tets.V.row(0) << 0, 0, 0;
  tets.V.row(1) << 0, 0, 1;
  const double pi = std::acos(-1.0);
  const int around[5] = {2, 4, 5, 6, 3};  // the fan's opposite vertices in order, at 0, 45, ..., 180 degrees
  for (int k = 0; k < 5; ++k) tets.V.row(around[k]) << std::cos(k * pi / 4), std::sin(k * pi / 4), 0.5;
  tets.T.resize(4, 4);
  for (int k = 0; k < 4; ++k) tets.T.row(k) << 0, 1, around[k], around[k + 1];
  Eigen::VectorXd f(7);
  f << 0.0, 0.0, 1.0, -1.0, 0.5, -0.1, 0.02;  // vertices 0 to 3 fixed (T1), 4 to 6 free
  const Midsurface m = zero_sheet(tets, f, 4, 0.0);
  EXPECT_EQ(m.settled, 1);
  EXPECT_DOUBLE_EQ(m.field(6), -0.02);
  EXPECT_DOUBLE_EQ(m.field(5), -0.1);
  int on_edge = 0;
  for (Eigen::Index t = 0; t < m.mesh.F.rows(); ++t) {
    int ends = 0;
    for (int k = 0; k < 3; ++k) {
      const int v = m.mesh.F(t, k);
      ends += m.edge(v, 0) == m.edge(v, 1) && m.edge(v, 0) < 2;
    }
    on_edge += ends == 2;
  }
  EXPECT_EQ(on_edge, 1);
  EXPECT_TRUE(analyze_sheet(m.mesh.F, m.mesh.V.rows()).edge_manifold);
}

}  // namespace
