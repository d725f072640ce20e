#include "igaprep/mesh/enclosed_volume.h"

#include <cmath>

#include <Eigen/Geometry>

namespace igaprep::mesh {

namespace {

// Six times the signed volume of the tetrahedron (origin, triangle f): the
// division by 6 is done once per sum.
double six_volume(const TriMesh& m, Eigen::Index f, const Eigen::Vector3d& origin) {
  const Eigen::Vector3d a = m.V.row(m.F(f, 0)).transpose() - origin, b = m.V.row(m.F(f, 1)).transpose() - origin,
                        c = m.V.row(m.F(f, 2)).transpose() - origin;
  return a.dot(b.cross(c));
}

}  // namespace

double enclosed_volume(const TriMesh& mesh, const Eigen::Vector3d& origin) {
  double v = 0.0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) v += six_volume(mesh, f, origin);
  return v / 6.0;
}

std::vector<double> enclosed_volumes(const TriMesh& mesh, const std::vector<int>& face_piece, int pieces,
                                     const Eigen::Vector3d& origin) {
  std::vector<double> v(static_cast<std::size_t>(pieces), 0.0);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    v[static_cast<std::size_t>(face_piece[static_cast<std::size_t>(f)])] += six_volume(mesh, f, origin);
  for (double& x : v) x /= 6.0;
  return v;
}

std::vector<double> region_volumes(const std::vector<TriMesh>& nested) {
  std::vector<double> enclosed;
  for (const TriMesh& s : nested) enclosed.push_back(std::abs(enclosed_volume(s)));
  std::vector<double> out;
  for (std::size_t i = 0; i < enclosed.size(); ++i)
    out.push_back(enclosed[i] - (i + 1 < enclosed.size() ? enclosed[i + 1] : 0.0));
  return out;
}

}  // namespace igaprep::mesh
