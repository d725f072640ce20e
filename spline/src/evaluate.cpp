// Evaluation of volumes, surfaces and curves. Single points contract the
// (p+1)^3 support directly; grids use sum factorisation over the 1-D basis
// tables (contract u, then v, then w), so a grid costs about
// (p+1) * 4 * (m_u n_v n_w + m_u m_v n_w + m_u m_v m_w) flops per derivative.
#include "igaprep/spline/evaluate.h"

#include <algorithm>
#include <cstring>

#include "igaprep/core/error.h"
#include "igaprep/spline/knot_vector.h"
#include "internal.h"

namespace igaprep::spline {

namespace {

constexpr int kMax = 32;

// Derivative multi-indices up to order 2 in slot order:
// 0:(0,0,0) 1:u 2:v 3:w 4:uu 5:vv 6:ww 7:uv 8:uw 9:vw
constexpr int kCombo[10][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {2, 0, 0},
                               {0, 2, 0}, {0, 0, 2}, {1, 1, 0}, {1, 0, 1}, {0, 1, 1}};
int combo_count(int order) { return order == 0 ? 1 : (order == 1 ? 4 : 10); }
int slot_of(int a) { return 1 + a; }  // first derivative along a
int slot_of(int a, int b) {           // second derivative along a, b
  if (a == b) return 4 + a;
  if (a > b) std::swap(a, b);
  return (a == 0) ? (b == 1 ? 7 : 8) : 9;
}

void check_order(int order) {
  if (order < 0 || order > 2) throw bad_input("evaluation: derivative order must be 0, 1 or 2");
}

// From homogeneous derivatives H[slot][c] (c < D) to Cartesian ones X[slot][0..2].
void to_cartesian(const double (*H)[4], int D, int order, double (*X)[3]) {
  const int nc = combo_count(order);
  if (D == 3) {
    for (int s = 0; s < nc; ++s)
      for (int c = 0; c < 3; ++c) X[s][c] = H[s][c];
    return;
  }
  const double W = H[0][3];
  for (int c = 0; c < 3; ++c) X[0][c] = H[0][c] / W;
  if (order >= 1)
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c) X[1 + a][c] = (H[1 + a][c] - H[1 + a][3] * X[0][c]) / W;
  if (order >= 2)
    for (int a = 0; a < 3; ++a)
      for (int b = a; b < 3; ++b) {
        const int s = slot_of(a, b);
        for (int c = 0; c < 3; ++c)
          X[s][c] = (H[s][c] - H[s][3] * X[0][c] - H[1 + a][3] * X[1 + b][c] -
                     H[1 + b][3] * X[1 + a][c]) / W;
      }
}

double clamp_param(const std::vector<double>& U, int p, double u) {
  const int n = basis_count(U, p);
  return std::min(std::max(u, U[p]), U[n]);
}

void check_patch_shape(const Patch& P) {
  const long n = static_cast<long>(P.count(0)) * P.count(1) * P.count(2);
  if (P.count(0) < 1 || P.count(1) < 1 || P.count(2) < 1 || P.control_points.rows() != n ||
      P.control_points.cols() != 3 || (P.rational() && P.weights.size() != n))
    throw bad_input("evaluation: patch control points (" + std::to_string(P.control_points.rows()) +
                    ") do not match its knot vectors and degrees (" + std::to_string(n) + ")");
}

// Homogeneous derivatives at one parameter: H[slot][c].
void point_homogeneous(const Patch& P, const Eigen::Vector3d& uvw, int order, double (*H)[4],
                       int* Dout) {
  check_patch_shape(P);
  const int D = P.rational() ? 4 : 3;
  *Dout = D;
  double N[3][3 * kMax];
  int span[3];
  for (int d = 0; d < 3; ++d) {
    const int p = P.degrees[d];
    const double u = clamp_param(P.knots[d], p, uvw[d]);
    span[d] = find_span(P.knots[d], p, u);
    basis_derivatives(P.knots[d], p, span[d], u, order, N[d]);
  }
  const int nc = combo_count(order);
  for (int s = 0; s < nc; ++s)
    for (int c = 0; c < 4; ++c) H[s][c] = 0.0;
  const int pu = P.degrees[0], pv = P.degrees[1], pw = P.degrees[2];
  const int nu = P.count(0), nv = P.count(1);
  const double* X = P.control_points.data();
  const long stride = P.control_points.rows();  // column-major n x 3
  const double* Wt = P.rational() ? P.weights.data() : nullptr;
  for (int k = 0; k <= pw; ++k)
    for (int j = 0; j <= pv; ++j) {
      const long base = (span[0] - pu) + static_cast<long>(nu) * ((span[1] - pv + j) +
                                                                  static_cast<long>(nv) * (span[2] - pw + k));
      // Contract u for derivative orders 0..order.
      double T[3][4] = {};
      for (int i = 0; i <= pu; ++i) {
        const long idx = base + i;
        double h[4] = {X[idx], X[idx + stride], X[idx + 2 * stride], 1.0};
        if (Wt) {
          const double w = Wt[idx];
          h[0] *= w, h[1] *= w, h[2] *= w, h[3] = w;
        }
        for (int du = 0; du <= order; ++du) {
          const double n = N[0][du * (pu + 1) + i];
          for (int c = 0; c < D; ++c) T[du][c] += n * h[c];
        }
      }
      for (int s = 0; s < nc; ++s) {
        const double f = N[1][kCombo[s][1] * (pv + 1) + j] * N[2][kCombo[s][2] * (pw + 1) + k];
        for (int c = 0; c < D; ++c) H[s][c] += f * T[kCombo[s][0]][c];
      }
    }
}

}  // namespace

PointDerivatives evaluate_derivatives(const Patch& p, const Eigen::Vector3d& uvw, int order) {
  check_order(order);
  double H[10][4], X[10][3];
  int D;
  point_homogeneous(p, uvw, order, H, &D);
  to_cartesian(H, D, order, X);
  PointDerivatives r;
  r.x = Eigen::Vector3d(X[0][0], X[0][1], X[0][2]);
  if (order >= 1)
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c) r.jacobian(c, a) = X[slot_of(a)][c];
  if (order >= 2)
    for (int c = 0; c < 3; ++c)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) r.hessian[c](a, b) = X[slot_of(a, b)][c];
  return r;
}

Eigen::Vector3d evaluate_point(const Patch& p, const Eigen::Vector3d& uvw) {
  double H[10][4];
  int D;
  point_homogeneous(p, uvw, 0, H, &D);
  if (D == 3) return Eigen::Vector3d(H[0][0], H[0][1], H[0][2]);
  return Eigen::Vector3d(H[0][0], H[0][1], H[0][2]) / H[0][3];
}

Eigen::Matrix3d evaluate_jacobian(const Patch& p, const Eigen::Vector3d& uvw) {
  return evaluate_derivatives(p, uvw, 1).jacobian;
}

Eigen::Vector3d evaluate_point(const Surface& s, const Eigen::Vector2d& uv) {
  return evaluate_point(as_patch(s), Eigen::Vector3d(uv[0], uv[1], 0.0));
}
Eigen::Matrix<double, 3, 2> evaluate_jacobian(const Surface& s, const Eigen::Vector2d& uv) {
  return evaluate_jacobian(as_patch(s), Eigen::Vector3d(uv[0], uv[1], 0.0)).leftCols<2>();
}
Eigen::Vector3d evaluate_point(const Curve& c, double u) {
  return evaluate_point(as_patch(c), Eigen::Vector3d(u, 0.0, 0.0));
}
Eigen::Vector3d evaluate_tangent(const Curve& c, double u) {
  return evaluate_jacobian(as_patch(c), Eigen::Vector3d(u, 0.0, 0.0)).col(0);
}

GridBasis grid_basis(const Patch& p, const std::array<std::vector<double>, 3>& params, int order) {
  check_order(order);
  GridBasis g;
  g.order = order;
  for (int d = 0; d < 3; ++d) {
    g.tables[d] = basis_table(p.knots[d], p.degrees[d], params[d], order);
    g.knots[d] = p.knots[d];
  }
  return g;
}

namespace {

// Sum factorisation, u and v contracted: the w-layers of control points
// that the grid's w parameters reach, each contracted to the grid's (u, v)
// points; layer w of the grid is then contract_w_layer's.
struct UvContraction {
  int D = 3;        // homogeneous coordinates (4 when rational)
  int k_first = 0;  // the first control layer in T2
  long slab = 0;    // m_u m_v D: one grid w-layer
  // T2[du * (order + 1) + dv][(k * m_v + j) * m_u * D + i * D + c]
  std::vector<std::vector<double>> T2;
};

UvContraction contract_uv(const Patch& P, const GridBasis& G, int order) {
  check_patch_shape(P);
  for (int d = 0; d < 3; ++d)
    if (G.tables[d].degree != P.degrees[d] || G.knots[d] != P.knots[d])
      throw bad_input("evaluate_grid: the grid basis was built for other knots or degrees (direction " +
                      std::to_string(d) + ")");
  if (order > G.order) throw bad_input("evaluate_grid: the grid basis holds fewer derivatives");
  UvContraction out;
  const int D = P.rational() ? 4 : 3;
  out.D = D;
  const Eigen::MatrixXd Hc = detail::homogeneous_points(P);
  const int nu = P.count(0), nv = P.count(1), nw = P.count(2);
  const int mu = G.size(0), mv = G.size(1), mw = G.size(2);
  const int pu = P.degrees[0], pv = P.degrees[1], pw = P.degrees[2];
  const BasisTable &Tu = G.tables[0], &Tv = G.tables[1], &Tw = G.tables[2];
  // Only the w-layers of control points the w parameters reach are
  // contracted (a grid of one element's w parameters needs p + 1 of them):
  // layers k_first .. k_first + layers - 1, stored from 0.
  int k_first = nw, k_last = -1;
  for (int k = 0; k < mw; ++k) {
    k_first = std::min(k_first, Tw.span[k] - pw);
    k_last = std::max(k_last, Tw.span[k]);
  }
  const int layers = std::max(0, k_last - k_first + 1);
  out.k_first = k_first;
  // Control points of those layers, point-major.
  std::vector<double> C(static_cast<size_t>(layers) * nv * nu * D);
  for (long i = 0; i < static_cast<long>(layers) * nv * nu; ++i)
    for (int c = 0; c < D; ++c) C[i * D + c] = Hc(static_cast<long>(k_first) * nv * nu + i, c);
  // Stage 1: contract u. T1[du][((k*nv + j)*mu + i)*D + c].
  std::vector<std::vector<double>> T1(order + 1);
  for (int du = 0; du <= order; ++du) {
    auto& t = T1[du];
    t.resize(static_cast<size_t>(layers) * nv * mu * D);
    for (long row = 0; row < static_cast<long>(layers) * nv; ++row) {
      const double* src = C.data() + row * nu * D;
      double* dst = t.data() + row * mu * D;
      for (int i = 0; i < mu; ++i) {
        const double* Nr = Tu.at(i, du);
        const double* s = src + static_cast<long>(Tu.span[i] - pu) * D;
        double acc[4] = {0, 0, 0, 0};
        for (int r = 0; r <= pu; ++r)
          for (int c = 0; c < D; ++c) acc[c] += Nr[r] * s[r * D + c];
        for (int c = 0; c < D; ++c) dst[i * D + c] = acc[c];
      }
    }
  }
  // Stage 2: contract v. T2[(du,dv)][((k*mv + j)*mu + i)*D + c].
  const long rowlen = static_cast<long>(mu) * D;
  out.slab = static_cast<long>(mv) * rowlen;
  out.T2.resize((order + 1) * (order + 1));
  for (int du = 0; du <= order; ++du)
    for (int dv = 0; du + dv <= order; ++dv) {
      auto& t = out.T2[du * (order + 1) + dv];
      t.assign(static_cast<size_t>(layers) * mv * rowlen, 0.0);
      for (int k = 0; k < layers; ++k)
        for (int j = 0; j < mv; ++j) {
          const double* Nr = Tv.at(j, dv);
          double* dst = t.data() + (static_cast<long>(k) * mv + j) * rowlen;
          for (int r = 0; r <= pv; ++r) {
            const double f = Nr[r];
            const double* src = T1[du].data() + (static_cast<long>(k) * nv + Tv.span[j] - pv + r) * rowlen;
            for (long q = 0; q < rowlen; ++q) dst[q] += f * src[q];
          }
        }
    }
  return out;
}

// Stage 3 for grid w-layer k: H[s * slab + q], the homogeneous derivative
// `s` (kCombo order) at the layer's point q / D, coordinate q % D.
void contract_w_layer(const UvContraction& uv, const GridBasis& G, int order, int k, std::vector<double>& H) {
  const int pw = G.tables[2].degree, nc = combo_count(order);
  const long slab = uv.slab;
  H.assign(static_cast<size_t>(nc) * slab, 0.0);
  for (int s = 0; s < nc; ++s) {
    const int du = kCombo[s][0], dv = kCombo[s][1], dw = kCombo[s][2];
    const auto& in = uv.T2[du * (order + 1) + dv];
    const double* Nr = G.tables[2].at(k, dw);
    double* dst = H.data() + s * slab;
    for (int r = 0; r <= pw; ++r) {
      const double f = Nr[r];
      const double* src = in.data() + static_cast<long>(G.tables[2].span[k] - pw + r - uv.k_first) * slab;
      for (long q = 0; q < slab; ++q) dst[q] += f * src[q];
    }
  }
}

}  // namespace

// Each grid w-layer is contracted and converted while it is in cache; no
// array of the whole grid's homogeneous values is made (for large grids its
// fresh pages cost more than the arithmetic).
Eigen::MatrixXd evaluate_grid_points(const Patch& p, const GridBasis& basis) {
  const UvContraction uv = contract_uv(p, basis, 0);
  const int D = uv.D;
  const long layer_points = uv.slab / D;
  Eigen::MatrixXd X(basis.point_count(), 3);
  std::vector<double> H;
  for (int k = 0; k < basis.size(2); ++k) {
    contract_w_layer(uv, basis, 0, k, H);
    for (long q = 0; q < layer_points; ++q) {
      const double* h = H.data() + q * D;
      const double inv = (D == 4) ? 1.0 / h[3] : 1.0;
      for (int c = 0; c < 3; ++c) X(k * layer_points + q, c) = h[c] * inv;
    }
  }
  return X;
}

GridEvaluation evaluate_grid(const Patch& p, const GridBasis& basis) {
  const int order = basis.order;
  const UvContraction uv = contract_uv(p, basis, order);
  const int D = uv.D, nc = combo_count(order);
  const long layer_points = uv.slab / D;
  const long N = basis.point_count();
  GridEvaluation r;
  r.points.resize(N, 3);
  if (order >= 1) r.jacobians.resize(N, 9);
  if (order >= 2) r.second.resize(N, 18);
  std::vector<double> H;
  double h[10][4], X[10][3];
  for (int k = 0; k < basis.size(2); ++k) {
    contract_w_layer(uv, basis, order, k, H);
    for (long q = 0; q < layer_points; ++q) {
      const long i = k * layer_points + q;
      for (int s = 0; s < nc; ++s)
        for (int c = 0; c < D; ++c) h[s][c] = H[s * uv.slab + q * D + c];
      to_cartesian(h, D, order, X);
      for (int c = 0; c < 3; ++c) r.points(i, c) = X[0][c];
      if (order >= 1)
        for (int c = 0; c < 3; ++c)
          for (int a = 0; a < 3; ++a) r.jacobians(i, 3 * c + a) = X[1 + a][c];
      if (order >= 2)
        for (int k2 = 0; k2 < 6; ++k2)
          for (int c = 0; c < 3; ++c) r.second(i, 3 * k2 + c) = X[4 + k2][c];
    }
  }
  return r;
}

GridEvaluation evaluate_grid(const Patch& p, const std::array<std::vector<double>, 3>& params,
                             int order) {
  return evaluate_grid(p, grid_basis(p, params, order));
}

GridEvaluation evaluate_grid(const Surface& s, const std::array<std::vector<double>, 2>& params,
                             int order) {
  const GridEvaluation v = evaluate_grid(as_patch(s), {params[0], params[1], {0.0}}, order);
  GridEvaluation r;
  r.points = v.points;
  const long N = v.points.rows();
  if (order >= 1) {
    r.jacobians.resize(N, 6);
    for (int c = 0; c < 3; ++c)
      for (int a = 0; a < 2; ++a) r.jacobians.col(2 * c + a) = v.jacobians.col(3 * c + a);
  }
  if (order >= 2) {
    r.second.resize(N, 9);
    const int keep[3] = {0, 1, 3};  // uu, vv, uv
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c) r.second.col(3 * k + c) = v.second.col(3 * keep[k] + c);
  }
  return r;
}

GridEvaluation evaluate_grid(const Curve& c, const std::vector<double>& params, int order) {
  const GridEvaluation v = evaluate_grid(as_patch(c), {params, {0.0}, {0.0}}, order);
  GridEvaluation r;
  r.points = v.points;
  const long N = v.points.rows();
  if (order >= 1) {
    r.jacobians.resize(N, 3);
    for (int k = 0; k < 3; ++k) r.jacobians.col(k) = v.jacobians.col(3 * k);
  }
  if (order >= 2) r.second = v.second.leftCols(3);
  return r;
}

Eigen::MatrixXd evaluate_points(const Patch& p, const Eigen::MatrixXd& uvw) {
  if (uvw.cols() != 3) throw bad_input("evaluate_points: parameters must be N x 3");
  Eigen::MatrixXd X(uvw.rows(), 3);
  for (long i = 0; i < uvw.rows(); ++i) X.row(i) = evaluate_point(p, uvw.row(i).transpose()).transpose();
  return X;
}

}  // namespace igaprep::spline
