#pragma once
// Small deterministic meshes for the param tests and benchmarks.
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "igaprep/mesh/tet_mesh.h"
#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/models/shapes.h"

namespace param_test {

// Signed volume of tet (a, b, c, d).
inline double tet_volume(const Eigen::MatrixXd& V, int a, int b, int c, int d) {
  const Eigen::Vector3d x0 = V.row(a).transpose(), x1 = V.row(b).transpose(), x2 = V.row(c).transpose(),
                        x3 = V.row(d).transpose();
  return (x1 - x0).dot((x2 - x0).cross(x3 - x0)) / 6.0;
}

inline void orient_positive(const Eigen::MatrixXd& V, Eigen::MatrixXi& T) {
  for (Eigen::Index t = 0; t < T.rows(); ++t)
    if (tet_volume(V, T(t, 0), T(t, 1), T(t, 2), T(t, 3)) < 0) std::swap(T(t, 2), T(t, 3));
}

// Box [0,1]^3 with n^3 cubes, 6 tets per cube (all around the main diagonal,
// so neighbouring cubes match). jitter > 0 moves interior vertices randomly by
// up to jitter * h (seeded), which keeps every tet positive for jitter <= 0.15.
inline igaprep::mesh::TetMesh box_tets(int nx, int ny, int nz, double jitter = 0.0, unsigned seed = 1) {
  igaprep::mesh::TetMesh m;
  auto id = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
  m.V.resize((nx + 1) * (ny + 1) * (nz + 1), 3);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        Eigen::Vector3d p(double(i) / nx, double(j) / ny, double(k) / nz);
        if (jitter > 0 && i > 0 && i < nx && j > 0 && j < ny && k > 0 && k < nz)
          p += jitter * Eigen::Vector3d(U(rng) / nx, U(rng) / ny, U(rng) / nz);
        m.V.row(id(i, j, k)) = p.transpose();
      }
  m.T.resize(6 * nx * ny * nz, 4);
  // The six monotone lattice paths from corner 0 to corner 7 of a cube.
  static const int perm[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  int t = 0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (const auto& p : perm) {
          int c[3] = {i, j, k};
          m.T(t, 0) = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[p[s]];
            m.T(t, s + 1) = id(c[0], c[1], c[2]);
          }
          ++t;
        }
  orient_positive(m.V, m.T);
  m.material = Eigen::VectorXi::Zero(m.T.rows());
  return m;
}

// Boundary vertices of a box mesh (any coordinate at 0 or 1).
inline std::vector<int> box_boundary(const Eigen::MatrixXd& V) {
  std::vector<int> b;
  for (Eigen::Index i = 0; i < V.rows(); ++i)
    for (int a = 0; a < V.cols(); ++a)
      if (V(i, a) == 0.0 || V(i, a) == 1.0) {
        b.push_back(static_cast<int>(i));
        break;
      }
  return b;
}

// Planar unit square [0,1]^2 (z = 0), n x n squares split into 2 triangles
// with alternating diagonals; interior vertices jittered like box_tets.
inline igaprep::mesh::TriMesh square_tris(int n, double jitter = 0.0, unsigned seed = 1) {
  igaprep::mesh::TriMesh m;
  auto id = [&](int i, int j) { return i + (n + 1) * j; };
  m.V.resize((n + 1) * (n + 1), 3);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      Eigen::Vector3d p(double(i) / n, double(j) / n, 0.0);
      if (jitter > 0 && i > 0 && i < n && j > 0 && j < n) p += jitter / n * Eigen::Vector3d(U(rng), U(rng), 0.0);
      m.V.row(id(i, j)) = p.transpose();
    }
  m.F.resize(2 * n * n, 3);
  int f = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if ((i + j) % 2 == 0) {
        m.F.row(f++) << a, b, c;
        m.F.row(f++) << a, c, d;
      } else {
        m.F.row(f++) << a, b, d;
        m.F.row(f++) << b, c, d;
      }
    }
  return m;
}

// Unit icosphere: icosahedron subdivided `level` times, vertices projected
// onto the sphere, triangles counter-clockwise seen from outside.
inline igaprep::mesh::TriMesh icosphere(int level) { return igaprep::models::make_ellipsoid(1.0, 1.0, 1.0, level); }

// Spherical shell a < r < b: `layers` prism layers over an icosphere of the
// given level, each prism split into 3 tets by the global vertex order (so
// neighbouring prisms match). Vertices of layer 0 lie exactly at r = a, of the
// last layer at r = b. F = inner sphere triangles (marker 1), then the outer
// ones (marker 0), as in tetrahedralize's convention (T1 = outer surface).
struct Shell {
  igaprep::mesh::TetMesh mesh;
  std::vector<int> inner, outer;  // vertices at r = a and r = b
  Eigen::MatrixXi inner_faces;    // triangles of the inner sphere
};

inline Shell spherical_shell(int level, int layers, double a = 1.0, double b = 2.0) {
  const igaprep::mesh::TriMesh s = icosphere(level);
  const int nv = static_cast<int>(s.V.rows());
  Shell out;
  auto& m = out.mesh;
  m.V.resize(nv * (layers + 1), 3);
  for (int l = 0; l <= layers; ++l) {
    const double r = a + (b - a) * l / layers;
    m.V.middleRows(l * nv, nv) = r * s.V;
  }
  m.T.resize(3 * s.F.rows() * layers, 4);
  int t = 0;
  for (int l = 0; l < layers; ++l)
    for (Eigen::Index f = 0; f < s.F.rows(); ++f) {
      std::array<int, 3> v = {s.F(f, 0), s.F(f, 1), s.F(f, 2)};
      std::sort(v.begin(), v.end());
      const int o = l * nv, p = (l + 1) * nv;
      m.T.row(t++) << o + v[0], o + v[1], o + v[2], p + v[0];
      m.T.row(t++) << o + v[1], o + v[2], p + v[0], p + v[1];
      m.T.row(t++) << o + v[2], p + v[0], p + v[1], p + v[2];
    }
  orient_positive(m.V, m.T);
  m.material = Eigen::VectorXi::Zero(m.T.rows());
  m.F.resize(2 * s.F.rows(), 3);
  m.F_marker.resize(2 * s.F.rows());
  for (Eigen::Index f = 0; f < s.F.rows(); ++f) {
    m.F.row(f) = s.F.row(f);
    m.F_marker(f) = 1;
    m.F.row(s.F.rows() + f) = s.F.row(f).array() + layers * nv;
    m.F_marker(s.F.rows() + f) = 0;
  }
  out.inner_faces = s.F;
  for (int i = 0; i < nv; ++i) {
    out.inner.push_back(i);
    out.outer.push_back(layers * nv + i);
  }
  return out;
}

inline double shell_exact(double r, double a = 1.0, double b = 2.0) { return (a / r) * (b - r) / (b - a); }

}  // namespace param_test
