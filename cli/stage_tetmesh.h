#pragma once
// The tet-mesh stage: TetGen on the case's nested surfaces, a summary line,
// and the mesh as VTU in the output folder.
#include <string>

#include "case_file.h"
#include "case_surfaces.h"
#include "igaprep/mesh/tet_mesh.h"

namespace igaprep::cli {

struct TetMeshSummary {
  long tets = 0, vertices = 0;
  double volume = 0.0;
  std::vector<long> tets_per_material;
  std::vector<double> volume_per_material;
};

TetMeshSummary summarize(const mesh::TetMesh& tets, int materials);

// Tetrahedralizes and prints the summary; writes <output_dir>/tetmesh.vtu
// when vtu_path is not empty.
mesh::TetMesh run_tetmesh_stage(const CaseFile& c, const CaseSurfaces& surfaces, const std::string& vtu_path);

}  // namespace igaprep::cli
