#pragma once
// Turns the pieces of a closed surface that face inward (enclose negative
// volume) to face outward, the orientation every later step expects.
#include <vector>

#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::mesh {

// Inputs: a closed, manifold, consistently oriented surface (check_surface:
// closed, manifold and oriented); on any other surface the volumes that
// decide mean nothing.
// Output: the mesh with the triangles of every piece (connected through
// shared vertices) that encloses negative volume reversed; returns those
// pieces, numbered in the order of their first triangle, as
// SurfaceReport::inward_pieces numbers them. Vertices do not move.
std::vector<int> orient_outward(TriMesh& mesh);

}  // namespace igaprep::mesh
