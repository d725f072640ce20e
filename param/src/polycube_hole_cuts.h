#pragma once
// Sheet paths fixed on straight lines of the (u, v) domain (polycube_2d.h:
// an arm's neck, a cut from a hole's corner).
#include <vector>

#include <Eigen/Core>

#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::param::detail {

// Fixes a sheet path on the segment a -> b of the domain: its vertices'
// (u, v) spread by 3D arc length (a cut, an arm's neck).
void spread_on_segment(const mesh::TriMesh& sheet, const std::vector<int>& path, const Eigen::Vector2d& a,
                       const Eigen::Vector2d& b, Eigen::MatrixXd& uv, std::vector<char>& fixed);

}  // namespace igaprep::param::detail
