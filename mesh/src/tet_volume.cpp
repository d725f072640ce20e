#include "igaprep/mesh/tet_volume.h"

#include <Eigen/Geometry>

namespace igaprep::mesh {

double signed_tet_volume(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                         const Eigen::Vector3d& d) {
  return (b - a).cross(c - a).dot(d - a) / 6.0;
}

TetVolumes tet_volumes(const TetMesh& tets, int materials) {
  TetVolumes s;
  s.per_material.assign(static_cast<std::size_t>(materials), 0.0);
  s.tets_per_material.assign(static_cast<std::size_t>(materials), 0);
  for (Eigen::Index t = 0; t < tets.T.rows(); ++t) {
    const Eigen::Vector3d a = tets.V.row(tets.T(t, 0)), b = tets.V.row(tets.T(t, 1)), c = tets.V.row(tets.T(t, 2)),
                          d = tets.V.row(tets.T(t, 3));
    const double volume = signed_tet_volume(a, b, c, d);
    const int m = tets.material(t);
    if (m >= 0 && m < materials) {
      s.per_material[static_cast<std::size_t>(m)] += volume;
      s.tets_per_material[static_cast<std::size_t>(m)] += 1;
    }
    s.total += volume;
  }
  return s;
}

}  // namespace igaprep::mesh
