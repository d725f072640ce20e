#pragma once
// Volume enclosed by a closed triangle surface, by the divergence theorem:
// the sum over its triangles of the signed volumes of the tetrahedra they
// make with an origin. Positive when the triangles face outward (seen from
// outside counter-clockwise), negative when they face inward.
#include <vector>

#include <Eigen/Core>

#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::mesh {

// Inputs: a closed triangle surface; origin (any point: it does not change
// the exact value, and one near the surface keeps the round-off small).
// Output: the signed enclosed volume.
double enclosed_volume(const TriMesh& mesh, const Eigen::Vector3d& origin = Eigen::Vector3d::Zero());

// The same per piece: triangle f belongs to piece face_piece[f], in
// 0..pieces-1 (e.g. the connected components). Output: pieces volumes.
std::vector<double> enclosed_volumes(const TriMesh& mesh, const std::vector<int>& face_piece, int pieces,
                                     const Eigen::Vector3d& origin = Eigen::Vector3d::Zero());

// Nested closed surfaces, outermost first: the volume between surface i and
// surface i + 1 (the last: inside it), each surface counted outward.
std::vector<double> region_volumes(const std::vector<TriMesh>& nested);

}  // namespace igaprep::mesh
