#pragma once
// Helpers shared by the spline sources (not installed API).
#include <Eigen/Core>

#include "igaprep/spline/multipatch.h"

namespace igaprep::spline::detail {

// Control points as rows of homogeneous coordinates: (w x, w y, w z, w) for a
// rational patch, (x, y, z) otherwise.
inline Eigen::MatrixXd homogeneous_points(const Patch& p) {
  if (!p.rational()) return p.control_points;
  Eigen::MatrixXd H(p.control_points.rows(), 4);
  H.leftCols<3>() = p.control_points.array().colwise() * p.weights.array();
  H.col(3) = p.weights;
  return H;
}

// Inverse of homogeneous_points: sets control points (and weights when H has 4 columns).
inline void set_from_homogeneous(const Eigen::MatrixXd& H, Patch* p) {
  if (H.cols() == 4) {
    p->weights = H.col(3);
    p->control_points = H.leftCols<3>().array().colwise() / p->weights.array();
  } else {
    p->weights.resize(0);
    p->control_points = H;
  }
}

}  // namespace igaprep::spline::detail
