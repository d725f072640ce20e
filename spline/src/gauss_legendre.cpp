#include "igaprep/spline/gauss_legendre.h"

#include <cmath>

#include "igaprep/core/error.h"

namespace igaprep::spline {

void gauss_legendre(int n, Eigen::VectorXd& points, Eigen::VectorXd& weights) {
  if (n < 1 || n > 64) throw internal_error("gauss_legendre: unsupported number of points " + std::to_string(n));
  points.resize(n);
  weights.resize(n);
  const double pi = 3.14159265358979323846;
  // Newton's method on P_n from the Chebyshev-like first guess; roots are
  // symmetric, so compute the first half and mirror.
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double x = std::cos(pi * (i + 0.75) / (n + 0.5));
    double dp = 0.0;
    for (int iter = 0; iter < 100; ++iter) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      if (n == 1) p0 = 1.0;
      const double pn = (n == 1) ? x : p1;
      const double pnm1 = (n == 1) ? 1.0 : p0;
      dp = n * (x * pn - pnm1) / (x * x - 1.0);
      const double dx = pn / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    // Recompute the derivative at the converged root for the weight.
    double p0 = 1.0, p1 = x;
    for (int k = 2; k <= n; ++k) {
      const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
      p0 = p1;
      p1 = p2;
    }
    const double pn = (n == 1) ? x : p1;
    const double pnm1 = (n == 1) ? 1.0 : p0;
    dp = n * (x * pn - pnm1) / (x * x - 1.0);
    const double w = 2.0 / ((1.0 - x * x) * dp * dp);
    // x is the i-th largest root in [-1, 1]; map to [0, 1] (weights halve).
    points(n - 1 - i) = 0.5 * (1.0 + x);
    points(i) = 0.5 * (1.0 - x);
    weights(n - 1 - i) = 0.5 * w;
    weights(i) = 0.5 * w;
  }
}

}  // namespace igaprep::spline
