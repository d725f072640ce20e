#pragma once
// Small helpers shared by the param sources (not installed).
#include <algorithm>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products

#include "igaprep/param/gradient.h"

namespace igaprep::param::detail {

// Throws bad_input (naming `who`) unless cells has 3 or 4 columns and indexes V.
void check_cells(const Eigen::MatrixXd& V, const Eigen::MatrixXi& cells, const char* who);
[[noreturn]] void throw_degenerate(const char* who, Eigen::Index c, int k);

inline Eigen::Vector3d vrow(const Eigen::MatrixXd& V, int i) { return Eigen::Vector3d(V(i, 0), V(i, 1), V(i, 2)); }

// Barycentric gradients of cell c; returns the (signed for tets) measure, 0 if degenerate.
inline double cell_grad_phi(const Eigen::MatrixXd& V, const Eigen::MatrixXi& C, Eigen::Index c,
                            Eigen::Matrix<double, 4, 3>& gp) {
  return tet_barycentric_gradients(vrow(V, C(c, 0)), vrow(V, C(c, 1)), vrow(V, C(c, 2)), vrow(V, C(c, 3)), gp);
}
inline double cell_grad_phi(const Eigen::MatrixXd& V, const Eigen::MatrixXi& C, Eigen::Index c,
                            Eigen::Matrix<double, 3, 3>& gp) {
  return tri_barycentric_gradients(vrow(V, C(c, 0)), vrow(V, C(c, 1)), vrow(V, C(c, 2)), gp);
}

// Unsigned volume (tets) or area (triangles) of cell c.
inline double cell_measure(const Eigen::MatrixXd& V, const Eigen::MatrixXi& C, Eigen::Index c) {
  const Eigen::Vector3d x0 = vrow(V, C(c, 0));
  const Eigen::Vector3d e1 = vrow(V, C(c, 1)) - x0, e2 = vrow(V, C(c, 2)) - x0;
  if (C.cols() == 4) return std::abs(e1.dot(e2.cross(vrow(V, C(c, 3)) - x0))) / 6.0;
  return 0.5 * e1.cross(e2).norm();
}

// Distance from x to the segment [a, b] in 2D or 3D (to a when the segment
// has no length).
template <int N>
double distance_to_segment(const Eigen::Matrix<double, N, 1>& x, const Eigen::Matrix<double, N, 1>& a,
                           const Eigen::Matrix<double, N, 1>& b) {
  const Eigen::Matrix<double, N, 1> ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((x - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (x - (a + t * ab)).norm();
}

}  // namespace igaprep::param::detail
