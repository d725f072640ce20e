#pragma once
// Writing a triangle surface as binary STL, OBJ or OFF, chosen by the
// extension of `path` (case-insensitive), atomically (a temporary file renamed
// into place). OBJ and OFF keep every double exactly (shortest round-trip
// decimal form); binary STL stores single-precision floats.
#include <string>

#include "igaprep/core/error.h"  // the functions here throw igaprep::Error
#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::mesh {

// Inputs: path ending in .stl, .obj or .off; mesh with valid indices.
// Throws Error(BadInput) for another extension, invalid indices or a write
// failure (then `path` is left untouched).
void write_surface(const std::string& path, const TriMesh& mesh);

}  // namespace igaprep::mesh
