#pragma once
// The surfaces of a case, read, checked, offset and nested: the first stage
// of every job that starts from a case.
#include <string>
#include <vector>

#include "igaprep/mesh/check_surface.h"
#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/pipeline/case.h"

namespace igaprep::pipeline {

struct Surfaces {
  std::vector<mesh::TriMesh> meshes;         // T1..Tn, validated and outward
  std::vector<mesh::SurfaceReport> reports;  // one per surface
  std::vector<std::string> names;            // labels, for messages
};

// Reads every file surface (or takes the in-memory one), makes every offset
// surface, checks each and the nesting. Throws Error(BadInput) listing every
// defect found.
Surfaces load_surfaces(const Case& c);

}  // namespace igaprep::pipeline
