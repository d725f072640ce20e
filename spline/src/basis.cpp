// B-spline basis functions and derivatives (Cox-de Boor triangle, as in
// Piegl & Tiller A2.2/A2.3), and basis tables for lists of parameters.
#include "igaprep/spline/basis.h"

#include <algorithm>

#include "igaprep/core/error.h"
#include "igaprep/spline/knot_vector.h"

namespace igaprep::spline {

namespace {
constexpr int kMax = 32;  // degrees up to 30 (validate_knot_vector)
}

void basis_functions(const std::vector<double>& U, int p, int span, double u, double* N) {
  double left[kMax], right[kMax];
  N[0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = u - U[span + 1 - j];
    right[j] = U[span + j] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      const double t = N[r] / (right[r + 1] + left[j - r]);
      N[r] = saved + right[r + 1] * t;
      saved = left[j - r] * t;
    }
    N[j] = saved;
  }
}

Eigen::VectorXd basis_functions(const std::vector<double>& U, int p, int span, double u) {
  Eigen::VectorXd N(p + 1);
  basis_functions(U, p, span, u, N.data());
  return N;
}

void basis_derivatives(const std::vector<double>& U, int p, int span, double u, int order,
                       double* ders) {
  if (p >= kMax - 1) throw bad_input("basis_derivatives: degree above 30");
  double ndu[kMax][kMax], a[2][kMax], left[kMax], right[kMax];
  ndu[0][0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = u - U[span + 1 - j];
    right[j] = U[span + j] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      ndu[j][r] = right[r + 1] + left[j - r];  // knot differences (lower triangle)
      const double t = ndu[r][j - 1] / ndu[j][r];
      ndu[r][j] = saved + right[r + 1] * t;    // basis functions (upper triangle)
      saved = left[j - r] * t;
    }
    ndu[j][j] = saved;
  }
  const int w = p + 1;
  for (int j = 0; j <= p; ++j) ders[j] = ndu[j][p];
  const int nd = std::min(order, p);
  for (int r = 0; r <= p; ++r) {
    int s1 = 0, s2 = 1;
    a[0][0] = 1.0;
    for (int k = 1; k <= nd; ++k) {
      double d = 0.0;
      const int rk = r - k, pk = p - k;
      if (r >= k) {
        a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
        d = a[s2][0] * ndu[rk][pk];
      }
      const int j1 = (rk >= -1) ? 1 : -rk;
      const int j2 = (r - 1 <= pk) ? k - 1 : p - r;
      for (int j = j1; j <= j2; ++j) {
        a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
        d += a[s2][j] * ndu[rk + j][pk];
      }
      if (r <= pk) {
        a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
        d += a[s2][k] * ndu[r][pk];
      }
      ders[k * w + r] = d;
      std::swap(s1, s2);
    }
  }
  double f = p;
  for (int k = 1; k <= nd; ++k) {
    for (int j = 0; j <= p; ++j) ders[k * w + j] *= f;
    f *= (p - k);
  }
  for (int k = nd + 1; k <= order; ++k)
    for (int j = 0; j <= p; ++j) ders[k * w + j] = 0.0;
}

Eigen::MatrixXd basis_derivatives(const std::vector<double>& U, int p, int span, double u,
                                  int order) {
  std::vector<double> d(static_cast<size_t>(order + 1) * (p + 1));
  basis_derivatives(U, p, span, u, order, d.data());
  Eigen::MatrixXd M(order + 1, p + 1);
  for (int k = 0; k <= order; ++k)
    for (int j = 0; j <= p; ++j) M(k, j) = d[k * (p + 1) + j];
  return M;
}

namespace {

// A table of `count` parameters, its rows not filled yet.
BasisTable empty_table(int p, int order, std::size_t count) {
  BasisTable t;
  t.degree = p;
  t.order = order;
  t.span.resize(count);
  t.values.resize(count * (order + 1) * (p + 1));
  return t;
}

// Row i of the table: parameter u in knot span `span`.
void fill_row(BasisTable& t, const std::vector<double>& U, std::size_t i, int span, double u) {
  t.span[i] = span;
  basis_derivatives(U, t.degree, span, u, t.order, t.values.data() + i * (t.order + 1) * (t.degree + 1));
}

}  // namespace

BasisTable basis_table(const std::vector<double>& U, int p, const std::vector<double>& params,
                       int order) {
  BasisTable t = empty_table(p, order, params.size());
  const int n = basis_count(U, p);
  for (size_t i = 0; i < params.size(); ++i) {
    const double u = std::min(std::max(params[i], U[p]), U[n]);
    fill_row(t, U, i, find_span(U, p, u), u);
  }
  return t;
}

BasisTable basis_table_on_span(const std::vector<double>& U, int p, int span, const std::vector<double>& params,
                               int order) {
  BasisTable t = empty_table(p, order, params.size());
  for (size_t i = 0; i < params.size(); ++i) fill_row(t, U, i, span, params[i]);
  return t;
}

Eigen::MatrixXd collocation_matrix(const std::vector<double>& U, int p,
                                   const std::vector<double>& params, int derivative) {
  const BasisTable t = basis_table(U, p, params, derivative);
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(static_cast<int>(params.size()), basis_count(U, p));
  for (int i = 0; i < t.size(); ++i) {
    const double* v = t.at(i, derivative);
    for (int r = 0; r <= p; ++r) B(i, t.span[i] - p + r) = v[r];
  }
  return B;
}

void bernstein_basis(int p, double t, double* B) {
  // de Casteljau-style triangle: stable for t in [0, 1].
  B[0] = 1.0;
  const double s = 1.0 - t;
  for (int j = 1; j <= p; ++j) {
    double saved = 0.0;
    for (int k = 0; k < j; ++k) {
      const double tmp = B[k];
      B[k] = saved + s * tmp;
      saved = t * tmp;
    }
    B[j] = saved;
  }
}

}  // namespace igaprep::spline
