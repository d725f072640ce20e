#include "igaprep/mesh/principal_axes.h"

#include <Eigen/Eigenvalues>

#include "igaprep/core/error.h"

namespace igaprep::mesh {

PrincipalAxes surface_principal_axes(const TriMesh& surface) {
  // Each face's area is split over its corners.
  double area = 0.0;
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  Eigen::VectorXd w = Eigen::VectorXd::Zero(surface.V.rows());
  for (Eigen::Index f = 0; f < surface.F.rows(); ++f) {
    const Eigen::Vector3d a = surface.V.row(surface.F(f, 0)), b = surface.V.row(surface.F(f, 1)),
                          d = surface.V.row(surface.F(f, 2));
    const double A = 0.5 * (b - a).cross(d - a).norm();
    area += A;
    c += A * (a + b + d) / 3.0;
    for (int k = 0; k < 3; ++k) w(surface.F(f, k)) += A / 3.0;
  }
  if (!(area > 0.0)) throw bad_input("principal axes: the surface has no area");
  c /= area;
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  for (Eigen::Index i = 0; i < surface.V.rows(); ++i) {
    const Eigen::Vector3d d = surface.V.row(i).transpose() - c;
    C += w(i) * d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(C);  // ascending eigenvalues
  PrincipalAxes p;
  p.centroid = c;
  p.axes = eig.eigenvectors();
  for (int k = 0; k < 3; ++k) {
    Eigen::Index i;
    p.axes.col(k).cwiseAbs().maxCoeff(&i);
    if (p.axes(i, k) < 0) p.axes.col(k) *= -1.0;
  }
  return p;
}

}  // namespace igaprep::mesh
