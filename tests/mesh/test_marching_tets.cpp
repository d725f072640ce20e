// Marching tetrahedra (marching_tets.h).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "igaprep/mesh/enclosed_volume.h"
#include "igaprep/mesh/marching_tets.h"
#include "igaprep/mesh/tetrahedralize.h"
#include "igaprep/models/shapes.h"

namespace {

using igaprep::mesh::IsoSurface;

// Unit cube split into n^3 cells of 6 tets each (Kuhn subdivision), every tet
// positively oriented.
void cube_tets(int n, Eigen::MatrixXd& V, Eigen::MatrixXi& T) {
  auto id = [n](int i, int j, int k) { return i + (n + 1) * (j + (n + 1) * k); };
  V.resize((n + 1) * (n + 1) * (n + 1), 3);
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) V.row(id(i, j, k)) << double(i) / n, double(j) / n, double(k) / n;
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  std::vector<Eigen::RowVector4i> tets;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& p : perms) {
          int c[3] = {i, j, k};
          Eigen::RowVector4i t;
          t(0) = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[p[s]];
            t(s + 1) = id(c[0], c[1], c[2]);
          }
          const Eigen::Vector3d a = V.row(t(0)), b = V.row(t(1)), cc = V.row(t(2)), d = V.row(t(3));
          if ((b - a).dot((cc - a).cross(d - a)) < 0) std::swap(t(2), t(3));
          tets.push_back(t);
        }
  T.resize(tets.size(), 4);
  for (std::size_t i = 0; i < tets.size(); ++i) T.row(i) = tets[i];
}

Eigen::Vector3d normal(const IsoSurface& iso, Eigen::Index f) {
  const Eigen::Vector3d a = iso.mesh.V.row(iso.mesh.F(f, 0)), b = iso.mesh.V.row(iso.mesh.F(f, 1)),
                        c = iso.mesh.V.row(iso.mesh.F(f, 2));
  return 0.5 * (b - a).cross(c - a);
}

// Edge/t data reproduce the positions; the edge straddles the iso value.
void check_edge_data(const IsoSurface& iso, const Eigen::MatrixXd& V, const Eigen::VectorXd& field, double value) {
  ASSERT_EQ(iso.edge.rows(), iso.mesh.V.rows());
  ASSERT_EQ(iso.t.size(), iso.mesh.V.rows());
  ASSERT_EQ(iso.tet.size(), iso.mesh.F.rows());
  for (Eigen::Index i = 0; i < iso.mesh.V.rows(); ++i) {
    const int a = iso.edge(i, 0), b = iso.edge(i, 1);
    const Eigen::RowVector3d p = (1 - iso.t(i)) * V.row(a) + iso.t(i) * V.row(b);
    EXPECT_LE((p - iso.mesh.V.row(i)).norm(), 1e-14) << "vertex " << i;
    EXPECT_GE(iso.t(i), 0.0);
    EXPECT_LE(iso.t(i), 1.0);
    EXPECT_LE(std::min(field(a), field(b)), value);
    EXPECT_GE(std::max(field(a), field(b)), value);
  }
}

}  // namespace

TEST(MarchingTets, LinearFieldGivesPlaneAlongGradient) {
  Eigen::MatrixXd V;
  Eigen::MatrixXi T;
  cube_tets(5, V, T);
  const Eigen::Vector3d g(0.3, -0.5, 0.8);
  const Eigen::VectorXd field = V * g;
  const double value = 0.137;
  const IsoSurface iso = igaprep::mesh::marching_tets(V, T, field, value);
  ASSERT_GT(iso.mesh.F.rows(), 20);
  for (Eigen::Index i = 0; i < iso.mesh.V.rows(); ++i)
    EXPECT_NEAR(iso.mesh.V.row(i).dot(g) / g.norm(), value / g.norm(), 1e-12) << "vertex " << i;
  for (Eigen::Index f = 0; f < iso.mesh.F.rows(); ++f) {
    const Eigen::Vector3d n = normal(iso, f);
    if (n.norm() < 1e-14) continue;
    EXPECT_GT(n.normalized().dot(g.normalized()), 1 - 1e-9) << "triangle " << f;
  }
  check_edge_data(iso, V, field, value);
  // Each triangle lies in its tet: its vertices are on that tet's edges.
  for (Eigen::Index f = 0; f < iso.mesh.F.rows(); ++f)
    for (int c = 0; c < 3; ++c) {
      const int v = iso.mesh.F(f, c);
      int found = 0;
      for (int j = 0; j < 4; ++j) found += (T(iso.tet(f), j) == iso.edge(v, 0)) + (T(iso.tet(f), j) == iso.edge(v, 1));
      EXPECT_EQ(found, 2) << "triangle " << f;
    }
}

TEST(MarchingTets, IsoValueThroughVertices) {
  // x = 0.6 passes exactly through grid vertices (field == iso counts as above).
  Eigen::MatrixXd V;
  Eigen::MatrixXi T;
  cube_tets(5, V, T);
  const Eigen::VectorXd field = V.col(0) * 5.0;  // integers at the grid
  const IsoSurface iso = igaprep::mesh::marching_tets(V, T, field, 3.0);
  ASSERT_GT(iso.mesh.F.rows(), 0);
  double area = 0;
  for (Eigen::Index i = 0; i < iso.mesh.V.rows(); ++i) EXPECT_NEAR(iso.mesh.V(i, 0), 0.6, 1e-12);
  for (Eigen::Index f = 0; f < iso.mesh.F.rows(); ++f) {
    const Eigen::Vector3d n = normal(iso, f);
    EXPECT_GE(n(0), 0.0) << "triangle " << f << " faces against the gradient";
    area += n(0);
  }
  EXPECT_NEAR(area, 1.0, 1e-12);  // the cube's cross-section
  check_edge_data(iso, V, field, 3.0);
}

TEST(MarchingTets, DistanceInBallGivesClosedSphere) {
  igaprep::mesh::TetgenOptions opt;
  opt.max_volume = 5e-4;  // interior points, so that |x| is resolved
  const auto tm = igaprep::mesh::tetrahedralize({igaprep::models::make_ellipsoid(1, 1, 1, 3)}, {}, opt);
  Eigen::VectorXd field(tm.V.rows());
  for (Eigen::Index i = 0; i < tm.V.rows(); ++i) field(i) = tm.V.row(i).norm();
  const double r = 0.6;
  const IsoSurface iso = igaprep::mesh::marching_tets(tm.V, tm.T, field, r);
  const auto& F = iso.mesh.F;
  ASSERT_GT(F.rows(), 50);
  check_edge_data(iso, tm.V, field, r);

  // Closed, manifold and consistently oriented: every directed edge once, and
  // its reverse once.
  std::map<std::pair<int, int>, int> directed;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int c = 0; c < 3; ++c) ++directed[{F(f, c), F(f, (c + 1) % 3)}];
  for (const auto& [e, count] : directed) {
    EXPECT_EQ(count, 1) << "edge " << e.first << "-" << e.second;
    auto rev = directed.find({e.second, e.first});
    ASSERT_NE(rev, directed.end()) << "boundary edge " << e.first << "-" << e.second;
  }
  // Vertex fans are single discs: the faces around each vertex form one cycle.
  std::vector<std::map<int, int>> next(iso.mesh.V.rows());
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int c = 0; c < 3; ++c) next[F(f, c)][F(f, (c + 1) % 3)] = F(f, (c + 2) % 3);
  for (Eigen::Index v = 0; v < iso.mesh.V.rows(); ++v) {
    ASSERT_FALSE(next[v].empty());
    int start = next[v].begin()->first, cur = start, steps = 0;
    do {
      cur = next[v].at(cur);
      ++steps;
    } while (cur != start && steps <= static_cast<int>(next[v].size()));
    EXPECT_EQ(steps, static_cast<int>(next[v].size())) << "vertex " << v << " is not a manifold vertex";
  }
  const long edges = static_cast<long>(directed.size()) / 2;
  EXPECT_EQ(iso.mesh.V.rows() - edges + F.rows(), 2);  // Euler characteristic of a sphere

  // Normals towards increasing |x| = outward: positive enclosed volume near the ball's.
  const double vol = igaprep::mesh::enclosed_volume(iso.mesh);
  const double ball = 4.0 / 3.0 * M_PI * r * r * r;
  EXPECT_NEAR(vol, ball, 0.05 * ball);
  for (Eigen::Index i = 0; i < iso.mesh.V.rows(); ++i) EXPECT_NEAR(iso.mesh.V.row(i).norm(), r, 0.05 * r);
}

TEST(MarchingTets, NoCrossingGivesEmptySurface) {
  Eigen::MatrixXd V;
  Eigen::MatrixXi T;
  cube_tets(2, V, T);
  const Eigen::VectorXd field = V.col(0);
  const IsoSurface iso = igaprep::mesh::marching_tets(V, T, field, 5.0);
  EXPECT_EQ(iso.mesh.F.rows(), 0);
  EXPECT_EQ(iso.mesh.V.rows(), 0);
}
