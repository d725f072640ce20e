// H: T1 with T2..Tn and the base surface M embedded as tet faces (seed paper,
// section 5.1).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>

#include "decomposition_cache.h"
#include "igaprep/core/error.h"

using namespace igaprep::param;

namespace {
std::array<int, 3> key(int a, int b, int c) {
  std::array<int, 3> k{a, b, c};
  std::sort(k.begin(), k.end());
  return k;
}
class DecompositionMeshTest : public ::testing::TestWithParam<std::string> {};
}  // namespace

TEST(DecompositionMesh, FacesNotInTetsFindsTheMissingFace) {
  Eigen::MatrixXi T(2, 4);
  T << 0, 1, 2, 3, 1, 2, 3, 4;
  Eigen::MatrixXi F(4, 3);
  F << 2, 1, 0,  // a face of tet 0, other order
      3, 2, 1,   // shared by both
      0, 1, 4,   // no face
      4, 3, 2;   // a face of tet 1
  EXPECT_EQ(faces_not_in_tets(T, F), std::vector<int>{2});
}

TEST_P(DecompositionMeshTest, EveryTriangleOfMIsAMarkedTetFace) {
  const auto& c = decomposition_test::cached(GetParam(), false);
  const auto& H = c.H;
  const auto& model = c.mid->model;
  const auto& M = c.base.m.mesh;
  const int n = static_cast<int>(model.surfaces.size());
  ASSERT_EQ(H.num_surfaces, n);
  // The input vertices keep their positions at the recorded offsets.
  for (int k = 0; k < n; ++k)
    for (Eigen::Index i = 0; i < model.surfaces[k].V.rows(); ++i)
      ASSERT_EQ((H.tets.V.row(decomposition_vertex(H, k, static_cast<int>(i))) - model.surfaces[k].V.row(i)).norm(), 0.0);
  for (Eigen::Index i = 0; i < M.V.rows(); ++i)
    ASSERT_EQ((H.tets.V.row(decomposition_vertex(H, n, static_cast<int>(i))) - M.V.row(i)).norm(), 0.0);

  // Tet faces of H, collected here from the tets themselves.
  std::set<std::array<int, 3>> tet_faces;
  for (Eigen::Index t = 0; t < H.tets.T.rows(); ++t)
    for (int k = 0; k < 4; ++k)
      tet_faces.insert(key(H.tets.T(t, (k + 1) % 4), H.tets.T(t, (k + 2) % 4), H.tets.T(t, (k + 3) % 4)));
  std::set<std::array<int, 3>> marked_m;
  for (Eigen::Index f = 0; f < H.tets.F.rows(); ++f)
    if (H.tets.F_marker(f) == n) marked_m.insert(key(H.tets.F(f, 0), H.tets.F(f, 1), H.tets.F(f, 2)));
  EXPECT_EQ(marked_m.size(), static_cast<std::size_t>(M.F.rows()));
  int missing = 0, unmarked = 0;
  for (Eigen::Index f = 0; f < M.F.rows(); ++f) {
    const auto k = key(decomposition_vertex(H, n, M.F(f, 0)), decomposition_vertex(H, n, M.F(f, 1)),
                       decomposition_vertex(H, n, M.F(f, 2)));
    missing += !tet_faces.count(k);
    unmarked += !marked_m.count(k);
  }
  EXPECT_EQ(missing, 0);
  EXPECT_EQ(unmarked, 0);
  // So are T1..Tn, each under its own marker, and every tet is positive.
  for (int k = 0; k < n; ++k) {
    EXPECT_EQ(H.surface_faces[static_cast<std::size_t>(k)].size(), static_cast<std::size_t>(model.surfaces[k].F.rows()));
    for (int f : H.surface_faces[static_cast<std::size_t>(k)])
      ASSERT_TRUE(tet_faces.count(key(H.tets.F(f, 0), H.tets.F(f, 1), H.tets.F(f, 2)))) << "T" << k + 1 << " face " << f;
  }
  double vmin = 1e300;
  for (Eigen::Index t = 0; t < H.tets.T.rows(); ++t) {
    const Eigen::Vector3d a = H.tets.V.row(H.tets.T(t, 0)), b = H.tets.V.row(H.tets.T(t, 1)),
                          d = H.tets.V.row(H.tets.T(t, 2)), e = H.tets.V.row(H.tets.T(t, 3));
    vmin = std::min(vmin, (b - a).dot((d - a).cross(e - a)));
  }
  EXPECT_GT(vmin, 0.0);
  EXPECT_EQ(H.flat_tets, count_flat_tets(H.tets.T, vertex_surfaces(H)));
  EXPECT_EQ(H.chords_split, 0);
  std::printf("%s: H has %ld vertices, %ld tets (%d flat: all four vertices on one surface); M has %ld triangles, "
              "all marked tet faces\n",
              GetParam().c_str(), static_cast<long>(H.tets.V.rows()), static_cast<long>(H.tets.T.rows()), H.flat_tets,
              static_cast<long>(M.F.rows()));
}

// Splitting the surface chords: same volume per material, positive tets, the
// marked faces still tet faces, and no tet left with all vertices on one surface.
TEST_P(DecompositionMeshTest, SplittingChordsRemovesFlatTets) {
  const auto& c = decomposition_test::cached(GetParam(), false);
  DecompositionMesh H = c.H;
  std::vector<int> label = vertex_surfaces(H);
  const int flat_before = count_flat_tets(H.tets.T, label);
  auto volumes = [](const igaprep::mesh::TetMesh& m, double& vmin) {
    Eigen::Vector2d v = Eigen::Vector2d::Zero();
    vmin = 1e300;
    for (Eigen::Index t = 0; t < m.T.rows(); ++t) {
      const Eigen::Vector3d a = m.V.row(m.T(t, 0)), b = m.V.row(m.T(t, 1)), d = m.V.row(m.T(t, 2)), e = m.V.row(m.T(t, 3));
      const double vol = (b - a).dot((d - a).cross(e - a)) / 6.0;
      vmin = std::min(vmin, vol);
      v(m.material(t)) += vol;
    }
    return v;
  };
  double vmin0, vmin1;
  const Eigen::Vector2d before = volumes(H.tets, vmin0);
  const int split = split_surface_chords(H.tets, label, surface_edges(H));
  const Eigen::Vector2d after = volumes(H.tets, vmin1);
  std::printf("%s: %d flat tets, %d chords split, %d flat tets left; smallest tet volume %.3g -> %.3g\n",
              GetParam().c_str(), flat_before, split, count_flat_tets(H.tets.T, label), vmin0, vmin1);
  EXPECT_GT(split, 0);
  // What stays flat has no chord to split: all six edges are edges of one
  // surface (three of M's triangles around a valence-3 vertex; the header says so).
  std::set<std::pair<int, int>> on_surface;
  for (const auto& list : surface_edges(H))
    for (const auto& e : list) on_surface.insert(e);
  for (Eigen::Index t = 0; t < H.tets.T.rows(); ++t) {
    const int k = label[static_cast<std::size_t>(H.tets.T(t, 0))];
    bool flat = k >= 0;
    for (int j = 1; j < 4; ++j) flat = flat && label[static_cast<std::size_t>(H.tets.T(t, j))] == k;
    if (!flat) continue;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const int a = H.tets.T(t, i), b = H.tets.T(t, j);
        EXPECT_TRUE(on_surface.count({std::min(a, b), std::max(a, b)})) << "flat tet " << t << " has a chord";
      }
  }
  EXPECT_LT(count_flat_tets(H.tets.T, label), flat_before);
  EXPECT_EQ(static_cast<Eigen::Index>(label.size()), H.tets.V.rows());
  EXPECT_EQ(H.tets.V.rows(), c.H.tets.V.rows() + split);
  EXPECT_GT(vmin1, 0.0);
  EXPECT_LT((after - before).norm(), 1e-12 * before.norm());
  EXPECT_TRUE(faces_not_in_tets(H.tets.T, H.tets.F).empty());
}

TEST(DecompositionMesh, BaseSurfaceCrossingT2IsBadInput) {
  const auto& mid = midsurface_test::cached("sphere2");
  igaprep::mesh::TriMesh big = decomposition_test::cached("sphere2", false).base.m.mesh;
  const Eigen::RowVector3d centre = big.V.colwise().mean();
  big.V = ((big.V.rowwise() - centre) * 2.5).rowwise() + centre;  // reaches out through T2
  int outside = 0;
  for (Eigen::Index i = 0; i < big.V.rows(); ++i)
    outside += midsurface_test::winding_number(big.V.row(i).transpose(), mid.model.surfaces[1]) < 0.5;
  ASSERT_GT(outside, 0);  // some vertex outside T2 indeed
  try {
    decomposition_mesh(mid.model.surfaces, big);
    FAIL() << "no error";
  } catch (const igaprep::Error& e) {
    EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput);
    EXPECT_NE(std::string(e.what()).find("embedded surface 0"), std::string::npos) << e.what();
  }
  EXPECT_THROW(decomposition_mesh(mid.model.surfaces, igaprep::mesh::TriMesh{}), igaprep::Error);
}

INSTANTIATE_TEST_SUITE_P(Models, DecompositionMeshTest, ::testing::Values("sphere2", "ring2"),
                         [](const auto& info) { return info.param; });
