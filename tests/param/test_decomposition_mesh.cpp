// H: T1 with T2..Tn and the base surface M embedded as tet faces (seed paper,
// section 5.1).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>

#include "decomposition_cache.h"

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
  const auto& M = c.mid->result.base.mesh;
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
  std::printf("%s: H has %ld vertices, %ld tets; M has %ld triangles, all marked tet faces\n", GetParam().c_str(),
              static_cast<long>(H.tets.V.rows()), static_cast<long>(H.tets.T.rows()), static_cast<long>(M.F.rows()));
}

INSTANTIATE_TEST_SUITE_P(Models, DecompositionMeshTest, ::testing::Values("sphere2", "ring2"),
                         [](const auto& info) { return info.param; });
