// The blocks of the volume parameterization as one conforming tet mesh
// (blocks_tet_mesh.h), on blocks built by hand: boxes whose parameter
// directions are permuted and reversed against their neighbours', a curved
// shell sector, a folded cell, a collapsed side, and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "igaprep/core/error.h"
#include "igaprep/param/blocks_tet_mesh.h"

namespace {

using namespace igaprep;
using namespace igaprep::param;

constexpr double kPi = 3.14159265358979323846;

// A block sampled from a map of [0,1]^3 on m uniform parameters per direction
// (first direction fastest).
SampledBlock make_block(int m, const std::function<Eigen::Vector3d(double, double, double)>& map, int material = 0) {
  SampledBlock b;
  b.material = material;
  b.samples.resize(m * m * m, 3);
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        const double u = double(i) / (m - 1), v = double(j) / (m - 1), w = double(k) / (m - 1);
        b.samples.row(i + m * (j + m * k)) = map(u, v, w).transpose();
      }
  return b;
}

double tet_volume(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T, Eigen::Index t) {
  const Eigen::Vector3d a = V.row(T(t, 0));
  const Eigen::Vector3d e1 = V.row(T(t, 1)).transpose() - a, e2 = V.row(T(t, 2)).transpose() - a,
                        e3 = V.row(T(t, 3)).transpose() - a;
  return e1.cross(e2).dot(e3) / 6.0;
}

double total_volume(const mesh::TetMesh& m) {
  double s = 0.0;
  for (Eigen::Index t = 0; t < m.T.rows(); ++t) s += tet_volume(m.V, m.T, t);
  return s;
}

double triangle_area(const Eigen::MatrixXd& V, const std::array<int, 3>& f) {
  const Eigen::Vector3d a = V.row(f[0]), b = V.row(f[1]), c = V.row(f[2]);
  return 0.5 * (b - a).cross(c - a).norm();
}

// Triangles of the tets (sorted vertex triples) and how many tets have each.
std::map<std::array<int, 3>, int> face_counts(const Eigen::MatrixXi& T) {
  static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  std::map<std::array<int, 3>, int> count;
  for (Eigen::Index t = 0; t < T.rows(); ++t)
    for (const auto& f : kFaces) {
      std::array<int, 3> key{{T(t, f[0]), T(t, f[1]), T(t, f[2])}};
      std::sort(key.begin(), key.end());
      ++count[key];
    }
  return count;
}

// Conformity of a mesh of the box [0, size]: every triangle inside the box is
// shared by exactly two tets, every triangle on its boundary by one; returns
// the boundary triangles' total area.
double check_box_conforming(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T, const Eigen::Vector3d& size) {
  const auto on_boundary = [&](const std::array<int, 3>& f) {
    for (int d = 0; d < 3; ++d)
      for (double plane : {0.0, size[d]}) {
        bool all = true;
        for (int v : f) all = all && std::abs(V(v, d) - plane) < 1e-12;
        if (all) return true;
      }
    return false;
  };
  double area = 0.0;
  int bad = 0;
  for (const auto& [f, n] : face_counts(T)) {
    const bool boundary = on_boundary(f);
    if (n != (boundary ? 1 : 2)) ++bad;
    if (n == 1) area += triangle_area(V, f);
  }
  EXPECT_EQ(bad, 0) << "triangles with the wrong number of tets";
  return area;
}

// Sum over the marked faces of (centroid . normal) / 3: the enclosed volume
// when they close a region and are oriented outward (divergence theorem).
double enclosed_volume(const mesh::TetMesh& m, int marker) {
  double s = 0.0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    if (m.F_marker[f] != marker) continue;
    const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    s += ((a + b + c) / 3.0).dot(0.5 * (b - a).cross(c - a)) / 3.0;
  }
  return s;
}

double marked_area(const mesh::TetMesh& m, int marker) {
  double s = 0.0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    if (m.F_marker[f] == marker) s += triangle_area(m.V, {{m.F(f, 0), m.F(f, 1), m.F(f, 2)}});
  return s;
}

// Two unit cubes side by side sharing x = 1; the second one's parameters are
// (y, x - 1, 1 - z): directions swapped and one reversed (still positively
// oriented), so its Kuhn diagonals on the shared face cross the first one's.
std::vector<SampledBlock> two_cubes(int m, int material_b) {
  SampledBlock a = make_block(m, [](double u, double v, double w) { return Eigen::Vector3d(u, v, w); });
  SampledBlock b =
      make_block(m, [](double u, double v, double w) { return Eigen::Vector3d(1.0 + v, u, 1.0 - w); }, material_b);
  a.side_label = {{0, -1, 0, 0, 0, 0}};  // u1 is x = 1
  b.side_label = {{0, 0, -1, 0, 0, 0}};  // v0 is x = 1
  return {a, b};
}

TEST(BlocksTetMesh, PermutedReversedNeighboursConform) {
  for (int m : {3, 5}) {
    SCOPED_TRACE(m);
    const BlocksTetMesh r = blocks_tet_mesh(two_cubes(m, 0), 1e-9);
    const int cells = (m - 1) * (m - 1) * (m - 1);
    EXPECT_EQ(r.merged_points, m * m);
    EXPECT_EQ(r.collapsed_points, 0);
    EXPECT_EQ(r.tets.V.rows(), 2 * m * m * m - m * m);
    EXPECT_EQ(r.tets.T.rows(), 2 * 6 * cells);
    EXPECT_EQ(r.non_positive_tets, 0);
    EXPECT_EQ(r.collapsed_tets, 0);
    EXPECT_EQ(r.open_faces, 0);
    EXPECT_EQ(r.nonmanifold_faces, 0);
    EXPECT_NEAR(total_volume(r.tets), 2.0, 1e-12);
    EXPECT_NEAR(check_box_conforming(r.tets.V, r.tets.T, Eigen::Vector3d(2, 1, 1)), 10.0, 1e-12);
    // Marked faces: the ten labelled sides, outward.
    EXPECT_EQ(r.tets.F.rows(), 10 * 2 * (m - 1) * (m - 1));
    EXPECT_EQ((r.tets.F_marker.array() == 0).count(), r.tets.F.rows());
    EXPECT_NEAR(marked_area(r.tets, 0), 10.0, 1e-12);
    EXPECT_NEAR(enclosed_volume(r.tets, 0), 2.0, 1e-12);
    for (Eigen::Index t = 0; t < r.tets.T.rows(); ++t) {
      ASSERT_EQ(r.material[t], 0);
      ASSERT_EQ(r.block[t], t < 6 * cells ? 0 : 1);
    }
  }
}

// The test above can fail: the plain Kuhn split of both grids (each cell cut
// along its (0,0,0)-(1,1,1) diagonal) leaves the shared face cut crosswise.
TEST(BlocksTetMesh, PlainKuhnSplitWouldNotConform) {
  const int m = 3;
  const auto blocks = two_cubes(m, 0);
  std::map<std::array<long, 3>, int> ids;  // grid points by integer coordinates
  std::vector<Eigen::Vector3d> V;
  const auto id = [&](const Eigen::Vector3d& p) {
    const std::array<long, 3> key{{std::lround(p.x() * (m - 1)), std::lround(p.y() * (m - 1)), std::lround(p.z() * (m - 1))}};
    const auto it = ids.find(key);
    if (it != ids.end()) return it->second;
    V.push_back(p);
    return ids[key] = static_cast<int>(V.size()) - 1;
  };
  std::vector<std::array<int, 4>> tets;
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto& b : blocks)
    for (int k = 0; k + 1 < m; ++k)
      for (int j = 0; j + 1 < m; ++j)
        for (int i = 0; i + 1 < m; ++i)
          for (const auto& p : perms) {  // path from (0,0,0) to (1,1,1) along the axes p
            std::array<int, 3> c{{0, 0, 0}};
            std::array<int, 4> t{};
            for (int s = 0; s < 4; ++s) {
              if (s > 0) c[p[s - 1]] = 1;
              t[s] = id(b.samples.row((i + c[0]) + m * ((j + c[1]) + m * (k + c[2]))).transpose());
            }
            tets.push_back(t);
          }
  Eigen::MatrixXi T(static_cast<Eigen::Index>(tets.size()), 4);
  for (std::size_t t = 0; t < tets.size(); ++t)
    for (int c = 0; c < 4; ++c) T(static_cast<Eigen::Index>(t), c) = tets[t][c];
  int unmatched_inside = 0;
  for (const auto& [f, n] : face_counts(T)) {
    bool on_shared = true;
    for (int v : f) on_shared = on_shared && std::abs(V[static_cast<std::size_t>(v)].x() - 1.0) < 1e-12;
    if (on_shared && n == 1) ++unmatched_inside;
  }
  // Each of the (m-1)^2 shared cell faces is cut two ways: 4 unmatched triangles.
  EXPECT_EQ(unmatched_inside, 4 * (m - 1) * (m - 1));
}

// Blocks of different materials: the shared face is marked once, 1000 + max material.
TEST(BlocksTetMesh, MaterialInterfaceIsMarked) {
  const int m = 4;
  const BlocksTetMesh r = blocks_tet_mesh(two_cubes(m, 2), 1e-9);
  const int cells = (m - 1) * (m - 1) * (m - 1);
  EXPECT_EQ((r.material.array() == 2).count(), 6 * cells);
  EXPECT_EQ(r.tets.material, r.material);
  EXPECT_EQ((r.tets.F_marker.array() == kInterfaceMarker + 2).count(), 2 * (m - 1) * (m - 1));
  EXPECT_EQ(r.tets.F.rows(), 11 * 2 * (m - 1) * (m - 1));
  EXPECT_NEAR(marked_area(r.tets, kInterfaceMarker + 2), 1.0, 1e-12);
  EXPECT_NEAR(marked_area(r.tets, 0), 10.0, 1e-12);
  for (Eigen::Index f = 0; f < r.tets.F.rows(); ++f)
    if (r.tets.F_marker[f] == kInterfaceMarker + 2)
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(r.tets.V(r.tets.F(f, c), 0), 1.0, 1e-15);
}

// A 2 x 2 x 2 stack of unit cubes, each parameterized through a random
// rotation of the cube, with samples off by 1e-13 between neighbours (as the
// pipeline's shared faces are): still conforming.
TEST(BlocksTetMesh, RandomlyRotatedStackConforms) {
  std::vector<Eigen::Matrix3d> rotations;  // the 24 signed permutations with det +1
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto& p : perms)
    for (int signs = 0; signs < 8; ++signs) {
      Eigen::Matrix3d R = Eigen::Matrix3d::Zero();
      for (int r = 0; r < 3; ++r) R(r, p[r]) = (signs >> r) & 1 ? -1.0 : 1.0;
      if (R.determinant() > 0) rotations.push_back(R);
    }
  ASSERT_EQ(rotations.size(), 24u);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-1e-13, 1e-13);
  const int m = 4;
  for (int trial = 0; trial < 3; ++trial) {
    std::vector<SampledBlock> blocks;
    for (int b = 0; b < 8; ++b) {
      const Eigen::Matrix3d R = rotations[rng() % 24];
      const Eigen::Vector3d offset(b & 1, (b >> 1) & 1, (b >> 2) & 1), c(0.5, 0.5, 0.5);
      blocks.push_back(make_block(m, [&](double u, double v, double w) {
        return Eigen::Vector3d(offset + c + R * (Eigen::Vector3d(u, v, w) - c));
      }));
      for (Eigen::Index r = 0; r < blocks.back().samples.rows(); ++r)
        for (int d = 0; d < 3; ++d) blocks.back().samples(r, d) += jitter(rng);
    }
    const BlocksTetMesh r = blocks_tet_mesh(blocks, 1e-9);
    EXPECT_EQ(r.tets.V.rows(), 7 * 7 * 7);  // (2 (m - 1) + 1)^3 distinct points
    EXPECT_EQ(r.merged_points, 8 * m * m * m - 7 * 7 * 7);
    EXPECT_EQ(r.non_positive_tets, 0);
    EXPECT_EQ(r.nonmanifold_faces, 0);
    EXPECT_EQ(r.open_faces, 6 * 4 * 2 * (m - 1) * (m - 1));  // the outer sides carry no label here
    EXPECT_NEAR(total_volume(r.tets), 8.0, 1e-11);
    EXPECT_NEAR(check_box_conforming(r.tets.V, r.tets.T, Eigen::Vector3d(2, 2, 2)), 24.0, 1e-11);
  }
}

// A quarter of a cylindrical shell, r in [1, 2], theta in [0, pi/2], z in
// [0, 1], sampled exactly: the tets' volume (chords in theta) converges to
// 3 pi / 4 at second order.
TEST(BlocksTetMesh, CurvedBlockVolumeConvergesAtSecondOrder) {
  const auto shell = [](double u, double v, double w) {
    const double r = 1.0 + u, theta = 0.5 * kPi * v;
    return Eigen::Vector3d(r * std::cos(theta), r * std::sin(theta), w);
  };
  const double exact = 0.75 * kPi;
  std::vector<double> error;
  for (int m : {5, 9}) {
    SampledBlock b = make_block(m, shell);
    b.side_label = {{0, 0, 0, 0, 0, 0}};
    const BlocksTetMesh r = blocks_tet_mesh({b}, 1e-9);
    EXPECT_EQ(r.non_positive_tets, 0);
    EXPECT_EQ(r.merged_points, 0);
    EXPECT_EQ(r.nonmanifold_faces, 0);
    EXPECT_EQ(r.open_faces, 0);
    const double vol = total_volume(r.tets);
    EXPECT_NEAR(enclosed_volume(r.tets, 0), vol, 1e-12);  // the marked sides close it, outward
    // Exactly the polygonal annulus sector of m - 1 chords times the height.
    const int n = m - 1;
    EXPECT_NEAR(vol, 1.5 * n * std::sin(0.5 * kPi / n), 1e-12);
    error.push_back(std::abs(vol - exact));
  }
  // Chord error ~ h^2: halving h divides it by about 4.
  EXPECT_NEAR(error[0], 0.0601, 1e-4);
  EXPECT_GT(error[0] / error[1], 3.8);
  EXPECT_LT(error[0] / error[1], 4.2);
}

// An interior sample pushed out of the unit cube folds its cells: tets of
// non-positive volume are counted, not thrown; the signed volume stays 1 (the
// boundary did not move).
TEST(BlocksTetMesh, FoldedCellIsCounted) {
  const int m = 3;
  SampledBlock b = make_block(m, [](double u, double v, double w) { return Eigen::Vector3d(u, v, w); });
  b.samples.row(1 + m * (1 + m * 1)) << 1.6, 1.6, 1.6;
  BlocksTetMesh r;
  ASSERT_NO_THROW(r = blocks_tet_mesh({b}, 1e-9));
  EXPECT_GT(r.non_positive_tets, 0);
  int negative = 0;
  for (Eigen::Index t = 0; t < r.tets.T.rows(); ++t) negative += tet_volume(r.tets.V, r.tets.T, t) <= 0.0;
  EXPECT_EQ(r.non_positive_tets, negative);
  EXPECT_NEAR(total_volume(r.tets), 1.0, 1e-12);
}

// A wedge: side w1 collapsed to the segment x = 0, z = 1 (as strategy 1's
// crest fans at M's boundary). Its repeated samples merge, the flat tets are
// left out, the rest fill the wedge exactly and conform.
TEST(BlocksTetMesh, CollapsedSideGivesAWedge) {
  const int m = 5;
  SampledBlock b =
      make_block(m, [](double u, double v, double w) { return Eigen::Vector3d(u * (1.0 - w), v, w); });
  b.collapsed[5] = true;
  b.side_label = {{0, 0, 0, 0, 0, 0}};
  BlocksTetMesh r;
  ASSERT_NO_THROW(r = blocks_tet_mesh({b}, 1e-9));
  EXPECT_EQ(r.collapsed_points, m * m - m);
  EXPECT_EQ(r.tets.V.rows(), m * m * m - (m * m - m));
  EXPECT_GT(r.collapsed_tets, 0);
  EXPECT_EQ(r.tets.T.rows() + r.collapsed_tets, 6 * (m - 1) * (m - 1) * (m - 1));
  EXPECT_EQ(r.non_positive_tets, 0);
  EXPECT_EQ(r.nonmanifold_faces, 0);
  EXPECT_NEAR(total_volume(r.tets), 0.5, 1e-12);
  // Boundary: the bottom, x = 0 and the slanted side (sqrt 2), two half squares.
  double boundary = 0.0;
  for (const auto& [f, n] : face_counts(r.tets.T)) {
    ASSERT_LE(n, 2);
    if (n == 1) boundary += triangle_area(r.tets.V, f);
  }
  EXPECT_NEAR(boundary, 3.0 + std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(marked_area(r.tets, 0), 3.0 + std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(enclosed_volume(r.tets, 0), 0.5, 1e-12);
}

TEST(BlocksTetMesh, BadInputThrows) {
  const auto cube = [](double u, double v, double w) { return Eigen::Vector3d(u, v, w); };
  const auto expect_bad = [](const std::vector<SampledBlock>& blocks, double tol) {
    try {
      blocks_tet_mesh(blocks, tol);
      ADD_FAILURE() << "no throw";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::BadInput) << e.what();
    }
  };
  expect_bad({make_block(3, cube), make_block(4, cube)}, 1e-9);  // different m
  SampledBlock wrong = make_block(3, cube);
  wrong.samples.conservativeResize(26, 3);
  expect_bad({wrong}, 1e-9);  // not m^3 samples
  SampledBlock two_columns = make_block(3, cube);
  two_columns.samples.conservativeResize(27, 2);
  expect_bad({two_columns}, 1e-9);
  SampledBlock nan = make_block(3, cube);
  nan.samples(4, 1) = std::nan("");
  expect_bad({nan}, 1e-9);
  expect_bad({}, 1e-9);
  expect_bad({make_block(3, cube)}, 0.0);
  expect_bad({make_block(3, cube)}, -1.0);
  expect_bad({make_block(1, cube)}, 1e-9);  // m = 1: no cells
}

}  // namespace
