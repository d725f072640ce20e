#include "igaprep/mesh/sharp_edges.h"

#include <Eigen/Geometry>
#include <unordered_map>

#include "igaprep/core/angle.h"
#include "igaprep/core/edge_key.h"

namespace igaprep::mesh {

std::vector<std::array<Eigen::Vector3d, 2>> sharp_edges(const TriMesh& mesh, double angle_degrees) {
  std::vector<Eigen::Vector3d> normal(mesh.F.rows());
  for (int f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    normal[f] = (b - a).cross(c - a);
  }
  std::unordered_map<std::uint64_t, int> first_face;
  std::vector<std::array<Eigen::Vector3d, 2>> out;
  for (int f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.F(f, k), b = mesh.F(f, (k + 1) % 3);
      const auto [it, added] = first_face.emplace(edge_key(a, b), f);
      if (added) continue;
      const Eigen::Vector3d &n = normal[it->second], &m = normal[f];
      if (igaprep::angle_degrees(n, m) > angle_degrees)
        out.push_back({{mesh.V.row(a).transpose(), mesh.V.row(b).transpose()}});
    }
  return out;
}

}  // namespace igaprep::mesh
