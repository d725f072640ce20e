#pragma once
// Drops the vertices no triangle uses (e.g. left in a file by its writer).
#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::mesh {

// Inputs: a triangle mesh with valid vertex indices.
// Output: the mesh without unreferenced vertices (the others keep their
// order; F renumbered); returns how many were removed.
int remove_unused_vertices(TriMesh& mesh);

}  // namespace igaprep::mesh
