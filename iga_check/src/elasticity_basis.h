#pragma once
// Internal to the elasticity solver: rational tensor-product basis values and
// physical gradients on one element, from 1-D tables built once per direction
// (the tensor structure: a volume element is a triple of 1-D elements).
#include <Eigen/Core>
#include <array>
#include <vector>

#include "igaprep/spline/basis.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::iga_check::detail {

// One element (non-empty knot span) of one direction with its quadrature:
// params u[q], weights w[q] (already scaled by the span length), and the
// spline basis table there (values and first derivatives of the p+1
// non-zero functions, starting at `first`).
struct DirElement {
  int first = 0;
  std::vector<double> u, w;
  spline::BasisTable basis;  // order 1
  double N(int q, int r) const { return basis.at(q, 0)[r]; }
  double dN(int q, int r) const { return basis.at(q, 1)[r]; }
  int size() const { return static_cast<int>(u.size()); }
};

// Every non-empty span of U with the Gauss rule (points gp, weights gw on [0,1]).
std::vector<DirElement> direction_elements(const std::vector<double>& U, int p, const Eigen::VectorXd& gp,
                                           const Eigen::VectorXd& gw);
// A single parameter (weight 1): point evaluation and the fixed direction of a side.
DirElement direction_point(const std::vector<double>& U, int p, double u);
// The elements of a patch in each direction, with degree + 1 + extra Gauss
// points: built once per patch, combined into volume elements (tensor structure).
std::array<std::vector<DirElement>, 3> patch_elements(const spline::Patch& p, int extra);

// Values on an element at the tensor quadrature points q = qu + nu*(qv + nv*qw),
// local basis a = iu + (pu+1)*(iv + (pv+1)*iw).
struct ElementValues {
  std::vector<int> local;  // patch control-point index of each local function
  Eigen::MatrixXd R;       // nq x n rational basis values
  Eigen::MatrixXd grad;    // nq x 3n physical gradients [d/dx | d/dy | d/dz] (if requested)
  Eigen::MatrixXd x;       // nq x 3 physical points
  Eigen::MatrixXd J;       // nq x 9 Jacobians, column 3*c + d = d x_c / d u_d
  Eigen::VectorXd det;     // nq Jacobian determinants
  Eigen::VectorXd w;       // nq tensor quadrature weights (products of the 1-D weights)
  // scratch
  Eigen::MatrixXd Du, Dv, Dw, X;
  Eigen::VectorXd lw;
};
void element_values(const spline::Patch& patch, const DirElement& eu, const DirElement& ev, const DirElement& ew,
                    bool need_grad, ElementValues& out);

}  // namespace igaprep::iga_check::detail
