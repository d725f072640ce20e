#pragma once
// Reading a closed triangle surface from STL (ASCII or binary), OBJ, OFF or
// PLY (ASCII, binary little or big endian). The format is detected from the
// file's content; the extension only breaks ties.
#include <string>

#include "igaprep/core/error.h"  // the functions here throw igaprep::Error
#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::mesh {

// Inputs: path of the file.
// Output: the surface as a TriMesh. Polygons are fan-triangulated; STL corners
// with identical coordinates are merged into one vertex (exactly, no
// tolerance); extra per-vertex values (colours, normals, texture coordinates)
// are ignored. Vertex order is the file's (STL: order of first appearance).
// Throws Error(BadInput) naming the file when it cannot be read, is empty or
// truncated, has an unknown format, a NaN or infinite coordinate, or a face
// that refers to a vertex that does not exist. Does not check topology: see
// check_surface.h.
TriMesh read_surface(const std::string& path);

}  // namespace igaprep::mesh
