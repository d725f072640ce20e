#pragma once
// The surfaces of a case, read, checked, offset and nested: the first stage
// of every command that starts from a case file.
#include <string>
#include <vector>

#include "case_file.h"
#include "igaprep/mesh/check_surface.h"
#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::cli {

struct CaseSurfaces {
  std::vector<mesh::TriMesh> meshes;           // T1..Tn, validated and outward
  std::vector<mesh::SurfaceReport> reports;    // one per surface
  std::vector<std::string> names;              // labels, for messages
};

// Reads every file surface, makes every offset surface, checks each and the
// nesting. Throws Error(BadInput) listing every defect found.
CaseSurfaces load_case_surfaces(const CaseFile& c);

}  // namespace igaprep::cli
