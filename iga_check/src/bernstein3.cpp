#include "igaprep/iga_check/bernstein3.h"

#include <Eigen/LU>

#include <cmath>
#include <string>

#include "igaprep/core/error.h"

namespace igaprep::iga_check {

namespace {

double binomial(int n, int k) {
  if (k < 0 || k > n) return 0.0;
  double r = 1.0;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

// Rows of Pascal's triangle up to the largest degree a product can have
// (the check refuses degrees over 40, a Jacobian's numerator is 3p - 1).
constexpr int kMaxBinomialRow = 128;

const std::vector<double>& binomial_row(int n) {
  static const std::vector<std::vector<double>> rows = [] {
    std::vector<std::vector<double>> r(kMaxBinomialRow + 1);
    for (int m = 0; m <= kMaxBinomialRow; ++m) {
      r[m].resize(m + 1);
      for (int k = 0; k <= m; ++k) r[m][k] = binomial(m, k);
    }
    return r;
  }();
  if (n < 0 || n > kMaxBinomialRow) throw internal_error("Bernstein3: degree " + std::to_string(n) + " out of range");
  return rows[n];
}

}  // namespace

Bernstein3::Bernstein3(const std::array<int, 3>& deg, double value) : degree(deg) {
  for (int d = 0; d < 3; ++d)
    if (deg[d] < 0) throw internal_error("Bernstein3: negative degree");
  coeffs.assign(static_cast<size_t>(size(0)) * size(1) * size(2), value);
}

Bernstein3 bernstein_product(const Bernstein3& a, const Bernstein3& b) {
  std::array<int, 3> deg;
  for (int d = 0; d < 3; ++d) deg[d] = a.degree[d] + b.degree[d];
  Bernstein3 c(deg, 0.0);
  // Scale both into the basis C(n,i) t^i (1-t)^(n-i) / ... : with scaled
  // coefficients the product is a plain convolution.
  std::array<const std::vector<double>*, 3> ba, bb, bc;
  for (int d = 0; d < 3; ++d) {
    ba[d] = &binomial_row(a.degree[d]);
    bb[d] = &binomial_row(b.degree[d]);
    bc[d] = &binomial_row(deg[d]);
  }
  std::vector<double> sb(b.coeffs.size());
  for (int k = 0; k < b.size(2); ++k)
    for (int j = 0; j < b.size(1); ++j)
      for (int i = 0; i < b.size(0); ++i) sb[b.index(i, j, k)] = b(i, j, k) * (*bb[0])[i] * (*bb[1])[j] * (*bb[2])[k];
  const int nb0 = b.size(0), nb1 = b.size(1), nb2 = b.size(2);
  const int nc0 = c.size(0), nc1 = c.size(1);
  for (int k = 0; k < a.size(2); ++k)
    for (int j = 0; j < a.size(1); ++j)
      for (int i = 0; i < a.size(0); ++i) {
        const double sa = a(i, j, k) * (*ba[0])[i] * (*ba[1])[j] * (*ba[2])[k];
        if (sa == 0.0) continue;
        for (int k2 = 0; k2 < nb2; ++k2)
          for (int j2 = 0; j2 < nb1; ++j2) {
            const double* src = sb.data() + nb0 * (j2 + nb1 * k2);
            double* dst = c.coeffs.data() + i + nc0 * ((j + j2) + nc1 * (k + k2));
            for (int i2 = 0; i2 < nb0; ++i2) dst[i2] += sa * src[i2];
          }
      }
  for (int k = 0; k < c.size(2); ++k)
    for (int j = 0; j < c.size(1); ++j)
      for (int i = 0; i < c.size(0); ++i) c(i, j, k) /= (*bc[0])[i] * (*bc[1])[j] * (*bc[2])[k];
  return c;
}

Bernstein3 bernstein_derivative(const Bernstein3& a, int dir) {
  std::array<int, 3> deg = a.degree;
  const int p = a.degree[dir];
  if (p == 0) return Bernstein3(deg, 0.0);
  deg[dir] = p - 1;
  Bernstein3 r(deg, 0.0);
  for (int k = 0; k < r.size(2); ++k)
    for (int j = 0; j < r.size(1); ++j)
      for (int i = 0; i < r.size(0); ++i) {
        std::array<int, 3> n{{i, j, k}};
        n[dir] += 1;
        r(i, j, k) = p * (a(n[0], n[1], n[2]) - a(i, j, k));
      }
  return r;
}

Bernstein3 bernstein_axpy(const Bernstein3& a, double s, const Bernstein3& b) {
  if (a.degree != b.degree) throw internal_error("bernstein_axpy: degrees differ");
  Bernstein3 r = a;
  for (size_t i = 0; i < r.coeffs.size(); ++i) r.coeffs[i] += s * b.coeffs[i];
  return r;
}

void bernstein_subdivide(const Bernstein3& a, int dir, double t, Bernstein3* low, Bernstein3* high) {
  *low = a;
  *high = a;
  const int n = a.degree[dir];
  const std::array<int, 3> stride{{1, a.size(0), a.size(0) * a.size(1)}};
  const int s = stride[dir];
  std::vector<double> work(n + 1);
  std::array<int, 3> other;
  int o = 0;
  for (int d = 0; d < 3; ++d)
    if (d != dir) other[o++] = d;
  for (int y = 0; y < a.size(other[1]); ++y)
    for (int x = 0; x < a.size(other[0]); ++x) {
      const int base = x * stride[other[0]] + y * stride[other[1]];
      for (int i = 0; i <= n; ++i) work[i] = a.coeffs[base + i * s];
      low->coeffs[base] = work[0];
      high->coeffs[base + n * s] = work[n];
      for (int r = 1; r <= n; ++r) {
        for (int i = 0; i <= n - r; ++i) work[i] = (1.0 - t) * work[i] + t * work[i + 1];
        low->coeffs[base + r * s] = work[0];
        high->coeffs[base + (n - r) * s] = work[n - r];
      }
    }
}

double bernstein_evaluate(const Bernstein3& a, const Eigen::Vector3d& t) {
  // Contract direction by direction with the Bernstein values.
  std::array<std::vector<double>, 3> B;
  for (int d = 0; d < 3; ++d) {
    const int n = a.degree[d];
    B[d].assign(n + 1, 0.0);
    for (int i = 0; i <= n; ++i)
      B[d][i] = binomial(n, i) * std::pow(t[d], i) * std::pow(1.0 - t[d], n - i);
  }
  double sum = 0.0;
  for (int k = 0; k < a.size(2); ++k)
    for (int j = 0; j < a.size(1); ++j) {
      double row = 0.0;
      for (int i = 0; i < a.size(0); ++i) row += a(i, j, k) * B[0][i];
      sum += row * B[1][j] * B[2][k];
    }
  return sum;
}

Bernstein3 bernstein_from_samples(const std::array<int, 3>& degree,
                                  const std::vector<double>& values) {
  Bernstein3 r(degree, 0.0);
  if (values.size() != r.coeffs.size()) throw internal_error("bernstein_from_samples: wrong sample count");
  // Solve the 1-D collocation system direction by direction (tensor structure).
  std::array<Eigen::PartialPivLU<Eigen::MatrixXd>, 3> lu;
  for (int d = 0; d < 3; ++d) {
    const int n = degree[d];
    Eigen::MatrixXd M(n + 1, n + 1);
    for (int a = 0; a <= n; ++a) {
      const double t = n == 0 ? 0.0 : double(a) / n;
      for (int i = 0; i <= n; ++i) M(a, i) = binomial(n, i) * std::pow(t, i) * std::pow(1.0 - t, n - i);
    }
    lu[d].compute(M);
  }
  r.coeffs = values;
  const std::array<int, 3> stride{{1, r.size(0), r.size(0) * r.size(1)}};
  for (int d = 0; d < 3; ++d) {
    const int n = degree[d] + 1;
    std::array<int, 3> other;
    int o = 0;
    for (int e = 0; e < 3; ++e)
      if (e != d) other[o++] = e;
    for (int y = 0; y < r.size(other[1]); ++y)
      for (int x = 0; x < r.size(other[0]); ++x) {
        const int base = x * stride[other[0]] + y * stride[other[1]];
        Eigen::VectorXd v(n);
        for (int i = 0; i < n; ++i) v[i] = r.coeffs[base + i * stride[d]];
        Eigen::VectorXd c = lu[d].solve(v);
        for (int i = 0; i < n; ++i) r.coeffs[base + i * stride[d]] = c[i];
      }
  }
  return r;
}

}  // namespace igaprep::iga_check
