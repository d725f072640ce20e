// Least-squares fitting of B-spline volumes (see fit.h for the methods).
#include "igaprep/spline/fit.h"

#include <Eigen/Cholesky>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <unsupported/Eigen/KroneckerProduct>

#include "igaprep/core/error.h"
#include "igaprep/spline/basis.h"
#include "igaprep/spline/gauss_legendre.h"
#include "igaprep/spline/knot_vector.h"

namespace igaprep::spline {

namespace {

using Mat = Eigen::MatrixXd;
const char* kDir[3] = {"u", "v", "w"};

// A tensor of coefficients, dims s[0..2] (u fastest), 3 components: stored as
// an (s0 s1 s2) x 3 column-major matrix, i.e. exactly like control points.
struct Tensor {
  std::array<int, 3> s{{0, 0, 0}};
  Mat data;
};

// Applies M (r x s[d]) along direction d.
Tensor apply_dir(const Tensor& T, const Mat& M, int d) {
  Tensor out;
  out.s = T.s;
  out.s[d] = static_cast<int>(M.rows());
  const long s0 = T.s[0], s1 = T.s[1], s2 = T.s[2];
  out.data.resize(static_cast<long>(out.s[0]) * out.s[1] * out.s[2], 3);
  if (d == 0) {
    Eigen::Map<const Mat> in(T.data.data(), s0, s1 * s2 * 3);
    Eigen::Map<Mat> o(out.data.data(), M.rows(), s1 * s2 * 3);
    o.noalias() = M * in;
  } else if (d == 1) {
    for (long slab = 0; slab < s2 * 3; ++slab) {
      Eigen::Map<const Mat> in(T.data.data() + slab * s0 * s1, s0, s1);
      Eigen::Map<Mat> o(out.data.data() + slab * s0 * M.rows(), s0, M.rows());
      o.noalias() = in * M.transpose();
    }
  } else {
    for (long c = 0; c < 3; ++c) {
      Eigen::Map<const Mat> in(T.data.data() + c * s0 * s1 * s2, s0 * s1, s2);
      Eigen::Map<Mat> o(out.data.data() + c * s0 * s1 * M.rows(), s0 * s1, M.rows());
      o.noalias() = in * M.transpose();
    }
  }
  return out;
}

Tensor apply_all(Tensor T, const std::array<Mat, 3>& M) {
  for (int d = 0; d < 3; ++d) T = apply_dir(T, M[d], d);
  return T;
}

// (B^T B)^{-1} B^T for a 1-D collocation matrix; bad_input when singular.
Mat ls_operator(const Mat& B, int d) {
  const Mat G = B.transpose() * B;
  Eigen::LLT<Mat> llt(G);
  const double scale = G.diagonal().maxCoeff();
  bool ok = llt.info() == Eigen::Success;
  if (ok) {
    const Eigen::VectorXd diag = Mat(llt.matrixL()).diagonal();
    ok = diag.minCoeff() * diag.minCoeff() > 1e-13 * scale;
  }
  if (!ok)
    throw bad_input(std::string("fit_grid: the samples do not determine every basis function in direction ") +
                    kDir[d] + " (put samples in the support of each basis function)");
  return llt.solve(B.transpose());
}

void check_inputs(const std::array<int, 3>& degrees, const std::array<std::vector<double>, 3>& knots,
                  const std::string& who) {
  for (int d = 0; d < 3; ++d)
    validate_knot_vector(knots[d], degrees[d], basis_count(knots[d], degrees[d]),
                         who + ": knot vector of direction " + kDir[d]);
}

Patch make_patch(const std::array<int, 3>& degrees, const std::array<std::vector<double>, 3>& knots, Mat cps) {
  Patch P;
  P.degrees = degrees;
  P.knots = knots;
  P.control_points = std::move(cps);
  return P;
}

void check_fixed(const FixedControlPoints& fixed, long n, const std::string& who) {
  if (fixed.values.rows() != static_cast<long>(fixed.indices.size()) || (!fixed.empty() && fixed.values.cols() != 3))
    throw bad_input(who + ": fixed control points need one row (x, y, z) per index");
  for (int i : fixed.indices)
    if (i < 0 || i >= n) throw bad_input(who + ": fixed control point index " + std::to_string(i) + " out of range");
}

}  // namespace

Patch fit_grid(const std::array<int, 3>& degrees, const std::array<std::vector<double>, 3>& knots,
               const std::array<std::vector<double>, 3>& params, const Eigen::MatrixXd& samples,
               const FixedControlPoints& fixed) {
  check_inputs(degrees, knots, "fit_grid");
  std::array<int, 3> n, m;
  for (int d = 0; d < 3; ++d) {
    n[d] = basis_count(knots[d], degrees[d]);
    m[d] = static_cast<int>(params[d].size());
  }
  const long N = static_cast<long>(m[0]) * m[1] * m[2];
  if (samples.rows() != N || samples.cols() != 3)
    throw bad_input("fit_grid: samples must be (m_u m_v m_w) x 3 = " + std::to_string(N) + " x 3, got " +
                    std::to_string(samples.rows()) + " x " + std::to_string(samples.cols()));
  if (!samples.allFinite()) throw bad_input("fit_grid: samples are not all finite");
  const long ncp = static_cast<long>(n[0]) * n[1] * n[2];
  check_fixed(fixed, ncp, "fit_grid");
  std::array<Mat, 3> B;
  for (int d = 0; d < 3; ++d) B[d] = collocation_matrix(knots[d], degrees[d], params[d], 0);
  Tensor S;
  S.s = m;
  S.data = samples;

  if (fixed.empty()) {
    std::array<Mat, 3> M;
    for (int d = 0; d < 3; ++d) M[d] = ls_operator(B[d], d);
    return make_patch(degrees, knots, apply_all(S, M).data);
  }

  // Fixed points: residual of the fixed part, then solve for the free ones.
  std::vector<char> is_fixed(ncp, 0);
  Tensor X0;
  X0.s = n;
  X0.data = Mat::Zero(ncp, 3);
  for (size_t k = 0; k < fixed.indices.size(); ++k) {
    is_fixed[fixed.indices[k]] = 1;
    X0.data.row(fixed.indices[k]) = fixed.values.row(k);
  }
  Tensor R = apply_all(X0, B);
  R.data = S.data - R.data;
  std::array<int, 3> lo{{n[0], n[1], n[2]}}, hi{{-1, -1, -1}};
  long nfree = 0;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
        if (!is_fixed[i + static_cast<long>(n[0]) * (j + static_cast<long>(n[1]) * k)]) {
          ++nfree;
          const int ijk[3] = {i, j, k};
          for (int d = 0; d < 3; ++d) lo[d] = std::min(lo[d], ijk[d]), hi[d] = std::max(hi[d], ijk[d]);
        }
  Mat out = X0.data;
  if (nfree == 0) return make_patch(degrees, knots, out);
  const long box = static_cast<long>(hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1);
  if (box == nfree) {
    // The free points form an index box: the restricted problem is again Kronecker.
    std::array<Mat, 3> M;
    for (int d = 0; d < 3; ++d) M[d] = ls_operator(B[d].middleCols(lo[d], hi[d] - lo[d] + 1), d);
    const Tensor Xb = apply_all(R, M);
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int i = lo[0]; i <= hi[0]; ++i)
          out.row(i + static_cast<long>(n[0]) * (j + static_cast<long>(n[1]) * k)) =
              Xb.data.row((i - lo[0]) + static_cast<long>(Xb.s[0]) * ((j - lo[1]) + static_cast<long>(Xb.s[1]) * (k - lo[2])));
    return make_patch(degrees, knots, out);
  }
  // General fixed set: preconditioned CG on the free unknowns of the normal
  // equations K x = B^T r with K = Gw (x) Gv (x) Gu applied direction by
  // direction; preconditioner = the unconstrained Kronecker inverse.
  std::array<Mat, 3> G, Bt, Ginv;
  for (int d = 0; d < 3; ++d) {
    G[d] = B[d].transpose() * B[d];
    Bt[d] = B[d].transpose();
    ls_operator(B[d], d);  // throws when G is singular
    Ginv[d] = G[d].llt().solve(Mat::Identity(n[d], n[d]));
  }
  auto mask = [&](Tensor& T) {
    for (long i = 0; i < ncp; ++i)
      if (is_fixed[i]) T.data.row(i).setZero();
  };
  Tensor rhs = apply_all(R, Bt);
  mask(rhs);
  Tensor x;
  x.s = n;
  x.data = Mat::Zero(ncp, 3);
  Tensor r = rhs;
  Tensor z = apply_all(r, Ginv);
  mask(z);
  Tensor p = z;
  Eigen::Array3d rz, rhs_norm;
  for (int c = 0; c < 3; ++c) {
    rz[c] = r.data.col(c).dot(z.data.col(c));
    rhs_norm[c] = std::max(rhs.data.col(c).norm(), 1e-300);
  }
  const int max_iter = static_cast<int>(std::min<long>(ncp, 5000)) + 50;
  int it = 0;
  for (; it < max_iter; ++it) {
    bool done = true;
    for (int c = 0; c < 3; ++c) done &= r.data.col(c).norm() <= 1e-14 * rhs_norm[c];
    if (done) break;
    Tensor Ap = apply_all(p, G);
    mask(Ap);
    for (int c = 0; c < 3; ++c) {
      const double pAp = p.data.col(c).dot(Ap.data.col(c));
      if (!(pAp > 0)) continue;
      const double alpha = rz[c] / pAp;
      x.data.col(c) += alpha * p.data.col(c);
      r.data.col(c) -= alpha * Ap.data.col(c);
    }
    z = apply_all(r, Ginv);
    mask(z);
    for (int c = 0; c < 3; ++c) {
      const double rz_new = r.data.col(c).dot(z.data.col(c));
      const double beta = rz[c] > 0 ? rz_new / rz[c] : 0.0;
      rz[c] = rz_new;
      p.data.col(c) = z.data.col(c) + beta * p.data.col(c);
    }
  }
  for (int c = 0; c < 3; ++c)
    if (r.data.col(c).norm() > 1e-10 * rhs_norm[c])
      throw internal_error("fit_grid: conjugate gradients with fixed control points did not converge in " +
                           std::to_string(it) + " iterations");
  for (long i = 0; i < ncp; ++i)
    if (!is_fixed[i]) out.row(i) = x.data.row(i);
  return make_patch(degrees, knots, out);
}

Surface fit_grid(const std::array<int, 2>& degrees, const std::array<std::vector<double>, 2>& knots,
                 const std::array<std::vector<double>, 2>& params, const Eigen::MatrixXd& samples,
                 const FixedControlPoints& fixed) {
  const Patch P = fit_grid({{degrees[0], degrees[1], 0}}, {{knots[0], knots[1], {0.0, 1.0}}},
                           {{params[0], params[1], {0.0}}}, samples, fixed);
  Surface s;
  s.degrees = degrees;
  s.knots = knots;
  s.control_points = P.control_points;
  return s;
}

namespace {

// 1-D Gram matrix of k-th derivatives, int N_i^(k) N_j^(k) du, sparse.
Eigen::SparseMatrix<double> derivative_gram(const std::vector<double>& U, int p, int k) {
  const int n = basis_count(U, p);
  Eigen::VectorXd gx, gw;  // on [0, 1]
  gauss_legendre(p + 1, gx, gw);
  Mat G = Mat::Zero(n, n);
  const std::vector<double> br = unique_knots(U);
  std::vector<double> ders(static_cast<size_t>(k + 1) * (p + 1));
  for (size_t e = 0; e + 1 < br.size(); ++e) {
    const double a = br[e], b = br[e + 1], h = b - a;
    for (int q = 0; q <= p; ++q) {
      const double u = a + h * gx[q];
      const int span = find_span(U, p, u);
      basis_derivatives(U, p, span, u, k, ders.data());
      const double* Nk = ders.data() + k * (p + 1);
      for (int i = 0; i <= p; ++i)
        for (int j = 0; j <= p; ++j) G(span - p + i, span - p + j) += gw[q] * h * Nk[i] * Nk[j];
    }
  }
  return G.sparseView(0.0, 0.0);
}

}  // namespace

Patch fit_scattered(const std::array<int, 3>& degrees, const std::array<std::vector<double>, 3>& knots,
                    const Eigen::MatrixXd& uvw, const Eigen::MatrixXd& points, double lambda,
                    const FixedControlPoints& fixed) {
  check_inputs(degrees, knots, "fit_scattered");
  if (uvw.cols() != 3 || points.cols() != 3 || uvw.rows() != points.rows())
    throw bad_input("fit_scattered: parameters and points must both be N x 3 with the same N");
  if (!(lambda >= 0) || !std::isfinite(lambda)) throw bad_input("fit_scattered: lambda must be finite and >= 0");
  if (!uvw.allFinite() || !points.allFinite()) throw bad_input("fit_scattered: non-finite parameters or points");
  std::array<int, 3> n;
  for (int d = 0; d < 3; ++d) n[d] = basis_count(knots[d], degrees[d]);
  const long ncp = static_cast<long>(n[0]) * n[1] * n[2];
  check_fixed(fixed, ncp, "fit_scattered");
  // Sparse collocation matrix, one row per sample.
  const long N = uvw.rows();
  std::vector<Eigen::Triplet<double>> trip;
  trip.reserve(static_cast<size_t>(N) * (degrees[0] + 1) * (degrees[1] + 1) * (degrees[2] + 1));
  double Nd[3][32];
  for (long s = 0; s < N; ++s) {
    int span[3];
    for (int d = 0; d < 3; ++d) {
      const auto& U = knots[d];
      const double u = std::min(std::max(uvw(s, d), U[degrees[d]]), U[n[d]]);
      span[d] = find_span(U, degrees[d], u);
      basis_functions(U, degrees[d], span[d], u, Nd[d]);
    }
    for (int k = 0; k <= degrees[2]; ++k)
      for (int j = 0; j <= degrees[1]; ++j)
        for (int i = 0; i <= degrees[0]; ++i) {
          const long col = (span[0] - degrees[0] + i) +
                           static_cast<long>(n[0]) * ((span[1] - degrees[1] + j) + static_cast<long>(n[1]) * (span[2] - degrees[2] + k));
          trip.emplace_back(static_cast<int>(s), static_cast<int>(col), Nd[0][i] * Nd[1][j] * Nd[2][k]);
        }
  }
  Eigen::SparseMatrix<double> B(N, ncp);
  B.setFromTriplets(trip.begin(), trip.end());
  Eigen::SparseMatrix<double> A = B.transpose() * B;
  if (lambda > 0) {
    std::array<std::array<Eigen::SparseMatrix<double>, 3>, 3> G;  // G[d][k]
    for (int d = 0; d < 3; ++d)
      for (int k = 0; k <= 2; ++k) G[d][k] = derivative_gram(knots[d], degrees[d], k);
    auto kron3 = [&](int ku, int kv, int kw) {
      Eigen::SparseMatrix<double> vu = Eigen::kroneckerProduct(G[1][kv], G[0][ku]);
      return Eigen::SparseMatrix<double>(Eigen::kroneckerProduct(G[2][kw], vu));
    };
    Eigen::SparseMatrix<double> K = kron3(2, 0, 0) + kron3(0, 2, 0) + kron3(0, 0, 2);
    K += 2.0 * (kron3(1, 1, 0) + kron3(1, 0, 1) + kron3(0, 1, 1));
    A += lambda * K;
  }
  Mat rhs = B.transpose() * points;
  // Eliminate fixed unknowns.
  std::vector<int> free_of(ncp, -1), free_list;
  std::vector<char> is_fixed(ncp, 0);
  Mat X = Mat::Zero(ncp, 3);
  for (size_t k = 0; k < fixed.indices.size(); ++k) {
    is_fixed[fixed.indices[k]] = 1;
    X.row(fixed.indices[k]) = fixed.values.row(k);
  }
  for (long i = 0; i < ncp; ++i)
    if (!is_fixed[i]) free_of[i] = static_cast<int>(free_list.size()), free_list.push_back(static_cast<int>(i));
  if (free_list.empty()) return make_patch(degrees, knots, X);
  if (!fixed.empty()) rhs -= A * X;
  std::vector<Eigen::Triplet<double>> tf;
  for (int c = 0; c < A.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, c); it; ++it)
      if (free_of[it.row()] >= 0 && free_of[it.col()] >= 0) tf.emplace_back(free_of[it.row()], free_of[it.col()], it.value());
  const int nf = static_cast<int>(free_list.size());
  Eigen::SparseMatrix<double> Af(nf, nf);
  Af.setFromTriplets(tf.begin(), tf.end());
  Mat bf(nf, 3);
  for (int i = 0; i < nf; ++i) bf.row(i) = rhs.row(free_list[i]);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(Af);
  bool ok = ldlt.info() == Eigen::Success;
  if (ok) {
    const double dmax = ldlt.vectorD().cwiseAbs().maxCoeff();
    ok = ldlt.vectorD().minCoeff() > 1e-14 * dmax;
  }
  if (!ok)
    throw bad_input("fit_scattered: the normal equations are singular: some basis functions have no samples in "
                    "their support (use lambda > 0 or more samples)");
  const Mat xf = ldlt.solve(bf);
  for (int i = 0; i < nf; ++i) X.row(free_list[i]) = xf.row(i);
  return make_patch(degrees, knots, X);
}

}  // namespace igaprep::spline
