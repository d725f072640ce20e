#pragma once
// The sharp edges of a triangle mesh: edges whose two triangles' normals
// differ by more than an angle (the mesh's creases, e.g. a blade's rim).
#include <Eigen/Core>
#include <array>
#include <vector>

#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::mesh {

// Each sharp edge as its two end points. Edges of one triangle only (a
// border) are not sharp edges.
std::vector<std::array<Eigen::Vector3d, 2>> sharp_edges(const TriMesh& mesh, double angle_degrees);

}  // namespace igaprep::mesh
