#pragma once
// Shared builders for the spline tests.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "igaprep/spline/spline.h"

namespace spline_test {
using namespace igaprep::spline;

// Random open knot vector: n functions of degree p on [a, b], interior knots
// random with some multiplicities up to max_mult.
inline std::vector<double> random_knots(std::mt19937& rng, int p, int n, int max_mult, double a = 0.0,
                                        double b = 1.0) {
  std::uniform_real_distribution<double> U(a, b);
  std::uniform_int_distribution<int> M(1, std::max(1, max_mult));
  std::vector<double> inner;
  while (static_cast<int>(inner.size()) < n - p - 1) {
    const double u = U(rng);
    const int m = std::min(M(rng), n - p - 1 - static_cast<int>(inner.size()));
    for (int i = 0; i < m; ++i) inner.push_back(u);
  }
  std::sort(inner.begin(), inner.end());
  std::vector<double> K(p + 1, a);
  K.insert(K.end(), inner.begin(), inner.end());
  K.insert(K.end(), p + 1, b);
  return K;
}

// A random (distorted box) patch, B-spline or NURBS.
inline Patch random_patch(std::mt19937& rng, std::array<int, 3> deg, std::array<int, 3> n, bool rational,
                          int max_mult = 1) {
  Patch P;
  P.degrees = deg;
  for (int d = 0; d < 3; ++d) P.knots[d] = random_knots(rng, deg[d], n[d], max_mult);
  std::uniform_real_distribution<double> J(-0.1, 0.1), W(0.5, 2.0);
  const int N = n[0] * n[1] * n[2];
  P.control_points.resize(N, 3);
  const auto g0 = greville_abscissae(P.knots[0], deg[0]);
  const auto g1 = greville_abscissae(P.knots[1], deg[1]);
  const auto g2 = greville_abscissae(P.knots[2], deg[2]);
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
        P.control_points.row(P.index(i, j, k)) =
            Eigen::RowVector3d(g0[i] + J(rng), 2 * g1[j] + J(rng), 3 * g2[k] + J(rng));
  if (rational) {
    P.weights.resize(N);
    for (int i = 0; i < N; ++i) P.weights[i] = W(rng);
  }
  return P;
}

// Exact NURBS quarter of the unit circle in the xy plane (quadratic, one span).
inline Curve quarter_circle() {
  Curve c;
  c.degree = 2;
  c.knots = {0, 0, 0, 1, 1, 1};
  c.control_points.resize(3, 3);
  c.control_points << 1, 0, 0, 1, 1, 0, 0, 1, 0;
  c.weights.resize(3);
  c.weights << 1, std::sqrt(0.5), 1;
  return c;
}

// Quarter annulus: u = angle (quadratic NURBS), v = radius 1..2, w = height 0..1.
inline Patch quarter_annulus() {
  Patch P;
  P.degrees = {{2, 1, 1}};
  P.knots = {{{0, 0, 0, 1, 1, 1}, {0, 0, 1, 1}, {0, 0, 1, 1}}};
  const double c[3][2] = {{1, 0}, {1, 1}, {0, 1}};
  const double w[3] = {1, std::sqrt(0.5), 1};
  P.control_points.resize(12, 3);
  P.weights.resize(12);
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) {
        const double r = 1.0 + j;
        P.control_points.row(P.index(i, j, k)) = Eigen::RowVector3d(r * c[i][0], r * c[i][1], k);
        P.weights[P.index(i, j, k)] = w[i];
      }
  return P;
}

inline Eigen::Vector3d random_param(std::mt19937& rng, const Patch& P) {
  Eigen::Vector3d u;
  for (int d = 0; d < 3; ++d) {
    const auto& K = P.knots[d];
    std::uniform_real_distribution<double> U(K.front(), K.back());
    u[d] = U(rng);
  }
  return u;
}

// Patch 0: a distorted box. Patch 1 glued to its u1 face with its own w0 face;
// a's v runs along b's u reversed, a's w along b's v in the same sense.
inline MultiPatch glued_patches(std::mt19937& rng, std::array<int, 3> degrees_a = {{2, 2, 1}},
                                std::array<int, 3> counts_a = {{4, 5, 3}},
                                std::vector<double> knots_w = {0, 0, 0, 0.5, 1, 1, 1}) {
  MultiPatch mp;
  Patch A = random_patch(rng, degrees_a, counts_a, true, 1);
  Patch B;
  // B's w degree: its end knot's multiplicity less one.
  const int pw = static_cast<int>(std::count(knots_w.begin(), knots_w.end(), knots_w.front())) - 1;
  B.degrees = {{A.degrees[1], A.degrees[2], pw}};
  std::vector<double> ku(A.knots[1].size());
  for (size_t k = 0; k < ku.size(); ++k) ku[k] = 1.0 - A.knots[1][ku.size() - 1 - k];
  B.knots = {{ku, A.knots[2], knots_w}};
  const int n0 = B.count(0), n1 = B.count(1), n2 = B.count(2);
  B.control_points.resize(n0 * n1 * n2, 3);
  B.weights.resize(n0 * n1 * n2);
  std::uniform_real_distribution<double> J(-0.05, 0.05);
  for (int k = 0; k < n2; ++k)
    for (int j = 0; j < n1; ++j)
      for (int i = 0; i < n0; ++i) {
        const int a = A.index(A.count(0) - 1, A.count(1) - 1 - i, j);
        Eigen::RowVector3d x = A.control_points.row(a) + Eigen::RowVector3d(0.4 * k, 0, 0);
        if (k > 0) x += Eigen::RowVector3d(J(rng), J(rng), J(rng));
        B.control_points.row(B.index(i, j, k)) = x;
        B.weights[B.index(i, j, k)] = k == 0 ? A.weights[a] : 1.0 + 0.1 * k;
      }
  mp.patches = {A, B};
  Interface itf;
  itf.patch_a = 0, itf.side_a = kU1, itf.patch_b = 1, itf.side_b = kW0;
  itf.dirmap = {{2, 0, 1}};
  itf.orient = {{1, 0, 1}};
  mp.interfaces = {itf};
  mp.labels = {"outer"};
  mp.materials = {Material{"steel", 210e9, 0.3}};
  return mp;
}

// Largest extent of the control points: the diagonal of their bounding box.
inline double diagonal(const MultiPatch& mp) {
  Eigen::RowVector3d lo = Eigen::RowVector3d::Constant(1e300), hi = -lo;
  for (const Patch& p : mp.patches) {
    lo = lo.cwiseMin(p.control_points.colwise().minCoeff());
    hi = hi.cwiseMax(p.control_points.colwise().maxCoeff());
  }
  return (hi - lo).norm();
}

}  // namespace spline_test
