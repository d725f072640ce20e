#pragma once
// Evaluation of B-spline and NURBS volumes (Patch), surfaces and curves:
// points, first derivatives (Jacobian) and second derivatives, at single
// parameters and on whole tensor grids of parameters. Grid evaluation builds
// the 1-D basis tables once (GridBasis) and reuses them for every point.
// Parameters outside the domain are clamped into it.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "igaprep/spline/basis.h"
#include "igaprep/spline/curve_surface.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::spline {

// ---- single parameters ----

// Point x(u, v, w) of a volume.
Eigen::Vector3d evaluate_point(const Patch& p, const Eigen::Vector3d& uvw);
// Jacobian J(c, d) = d x_c / d u_d (columns are the three parameter derivatives).
Eigen::Matrix3d evaluate_jacobian(const Patch& p, const Eigen::Vector3d& uvw);

struct PointDerivatives {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  Eigen::Matrix3d jacobian = Eigen::Matrix3d::Zero();  // (c, d) = d x_c / d u_d
  std::array<Eigen::Matrix3d, 3> hessian{};            // hessian[c](a, b) = d2 x_c / du_a du_b
};
// order 0: x only; 1: x and jacobian; 2: also hessian. Rational patches use
// the quotient rule on homogeneous derivatives.
PointDerivatives evaluate_derivatives(const Patch& p, const Eigen::Vector3d& uvw, int order);

Eigen::Vector3d evaluate_point(const Surface& s, const Eigen::Vector2d& uv);
Eigen::Matrix<double, 3, 2> evaluate_jacobian(const Surface& s, const Eigen::Vector2d& uv);
Eigen::Vector3d evaluate_point(const Curve& c, double u);
Eigen::Vector3d evaluate_tangent(const Curve& c, double u);  // dx/du

// ---- tensor grids ----

// 1-D basis tables of a patch's three directions at grid parameters.
struct GridBasis {
  std::array<BasisTable, 3> tables;
  std::array<std::vector<double>, 3> knots;  // of the patch the tables were built for
  int order = 0;
  int size(int d) const { return tables[d].size(); }
  int point_count() const { return size(0) * size(1) * size(2); }
};
GridBasis grid_basis(const Patch& p, const std::array<std::vector<double>, 3>& params, int order);

// Results at the grid points (u fastest, then v, then w), N = n_u*n_v*n_w.
struct GridEvaluation {
  Eigen::MatrixXd points;     // N x 3
  Eigen::MatrixXd jacobians;  // N x 9 when order >= 1: column 3*c + d = d x_c / d u_d
  Eigen::MatrixXd second;     // N x 18 when order >= 2: column 3*k + c = k-th second
                              // derivative of x_c, k = 0..5 for uu, vv, ww, uv, uw, vw
};

// The Jacobian at grid point `at` of an evaluate_grid result (J(c, d) = d x_c / d u_d).
inline Eigen::Matrix3d grid_jacobian(const GridEvaluation& ev, Eigen::Index at) {
  Eigen::Matrix3d J;
  for (int c = 0; c < 3; ++c)
    for (int d = 0; d < 3; ++d) J(c, d) = ev.jacobians(at, 3 * c + d);
  return J;
}

// Evaluates a patch at the grid the basis was built for (the basis must come
// from a patch with the same degrees and knots; checked, bad_input otherwise).
GridEvaluation evaluate_grid(const Patch& p, const GridBasis& basis);
GridEvaluation evaluate_grid(const Patch& p, const std::array<std::vector<double>, 3>& params,
                             int order);
// Points only, fast path: N x 3.
Eigen::MatrixXd evaluate_grid_points(const Patch& p, const GridBasis& basis);

// Surfaces: jacobians N x 6 (column 2*c + d), second N x 9 (uu, vv, uv).
GridEvaluation evaluate_grid(const Surface& s, const std::array<std::vector<double>, 2>& params,
                             int order);
// Curves: jacobians N x 3 (dx/du), second N x 3.
GridEvaluation evaluate_grid(const Curve& c, const std::vector<double>& params, int order);

// Many scattered parameters (rows of uvw, N x 3): points N x 3.
Eigen::MatrixXd evaluate_points(const Patch& p, const Eigen::MatrixXd& uvw);

}  // namespace igaprep::spline
