#pragma once
// Least-squares fitting of B-spline volumes to samples.
//  * fit_grid: samples on a tensor grid of parameters. Without fixed points the
//    normal equations are Kronecker products of 1-D Gram matrices and are solved
//    direction by direction (cost ~ n^4 for n^3 coefficients).
//    With fixed control points the full constrained least-squares problem is
//    solved (fixed unknowns eliminated): exactly by the same Kronecker solve when
//    the free points form an index box (fixed = union of whole faces / slabs),
//    else by conjugate gradients on the free unknowns with Kronecker mat-vecs,
//    preconditioned by the unconstrained Kronecker solve, to 1e-14 relative.
//  * fit_scattered: points with parameters, least squares plus lambda times the
//    thin-plate energy  int |d2x/du_a du_b|^2  over the parameter domain;
//    sparse normal equations solved with Eigen's sparse Cholesky (LDLT).
#include <Eigen/Core>
#include <array>
#include <vector>

#include "igaprep/spline/curve_surface.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::spline {

// Control points held fixed: indices into the patch's control points
// (u fastest) and their values (rows, x y z).
struct FixedControlPoints {
  std::vector<int> indices;
  Eigen::MatrixXd values;  // indices.size() x 3
  bool empty() const { return indices.empty(); }
};

// Inputs: degrees and knots of the result (B-spline), params[d] grid
// parameters per direction (m_d of them), samples (m_u*m_v*m_w) x 3 u fastest.
// Each direction needs enough samples: bad_input when a 1-D Gram matrix is singular.
// Output: a B-spline patch (material 0, no weights).
Patch fit_grid(const std::array<int, 3>& degrees, const std::array<std::vector<double>, 3>& knots,
               const std::array<std::vector<double>, 3>& params, const Eigen::MatrixXd& samples,
               const FixedControlPoints& fixed = {});

// Surface version (e.g. a boundary face fitted first): samples (m_u*m_v) x 3.
Surface fit_grid(const std::array<int, 2>& degrees, const std::array<std::vector<double>, 2>& knots,
                 const std::array<std::vector<double>, 2>& params, const Eigen::MatrixXd& samples,
                 const FixedControlPoints& fixed = {});

// Inputs: uvw N x 3 parameters, points N x 3, lambda >= 0 smoothing weight
// (the energy is not rescaled; lambda = 0 gives plain least squares, which
// then needs samples in the support of every basis function).
Patch fit_scattered(const std::array<int, 3>& degrees, const std::array<std::vector<double>, 3>& knots,
                    const Eigen::MatrixXd& uvw, const Eigen::MatrixXd& points, double lambda,
                    const FixedControlPoints& fixed = {});

}  // namespace igaprep::spline
