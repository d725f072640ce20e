#pragma once
// Gauss-Legendre quadrature on [0, 1], for every integral over knot spans
// (fitting's smoothing term, the check's volumes and quality points, the
// elasticity solve).
#include <Eigen/Core>

namespace igaprep::spline {

// Inputs: n >= 1 points.
// Outputs: points (n) in (0, 1), increasing; weights (n), summing to 1.
// Exact for polynomials of degree 2n - 1.
void gauss_legendre(int n, Eigen::VectorXd& points, Eigen::VectorXd& weights);

}  // namespace igaprep::spline
