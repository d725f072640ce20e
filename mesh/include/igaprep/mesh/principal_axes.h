#pragma once
// Area-weighted centroid and principal axes of a triangle surface.
#include <Eigen/Core>

#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::mesh {

struct PrincipalAxes {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  // unit columns, smallest spread first; each
                                                       // column's largest component is positive
};

// Throws bad_input when the surface has no area.
PrincipalAxes surface_principal_axes(const TriMesh& surface);

}  // namespace igaprep::mesh
