#pragma once
// Private helpers of the mesh module shared by check_surface and
// orient_outward, so that both number a surface's pieces and measure their
// volumes the same way. Not installed.
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::mesh::detail {

// Connected pieces of a triangle mesh (triangles joined through shared
// vertices), numbered in the order of their first triangle.
struct SurfacePieces {
  std::vector<int> of_face;     // piece of each triangle
  std::vector<int> face_count;  // triangles per piece
  int count() const { return static_cast<int>(face_count.size()); }
};
SurfacePieces surface_pieces(const TriMesh& mesh);

// Bounding box (min, max) of the vertices the triangles use.
std::pair<Eigen::Vector3d, Eigen::Vector3d> referenced_bounding_box(const TriMesh& mesh);

// Signed volume of each piece (enclosed_volumes), taken about the centre of
// the referenced bounding box to keep the round-off small.
std::vector<double> piece_volumes(const TriMesh& mesh, const SurfacePieces& pieces);

}  // namespace igaprep::mesh::detail
