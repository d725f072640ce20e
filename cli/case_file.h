#pragma once
// Case files (docs/case-format.md): the surfaces of a model, its materials,
// the output folder and the parameters of each stage, as one JSON object.
#include <optional>
#include <string>
#include <vector>

#include "igaprep/mesh/tetrahedralize.h"
#include "igaprep/param/midsurface_pipeline.h"
#include "igaprep/param/volume_param.h"
#include "igaprep/spline/block_fit.h"

namespace igaprep::cli {

struct CaseSurface {
  std::string label;
  std::string file;                 // absolute or relative to the working dir; empty for an offset
  std::optional<int> offset_of;     // index of an earlier surface to offset inward
  double inward = 0.0;              // offset distance (model units)
};

struct CaseMaterial {
  std::string name;
  double young_modulus = 0.0;
  double poisson_ratio = 0.0;
};

struct CaseFile {
  std::string path;        // the case file itself
  std::string name;        // case name (defaults to the file's folder name)
  std::vector<CaseSurface> surfaces;  // T1..Tn, outermost first
  std::vector<CaseMaterial> materials;  // one per surface: material i lies inside T(i+1)
  std::string output_dir;  // resolved against the case file's folder
  mesh::TetgenOptions tetmesh;
  param::MidsurfaceOptions midsurface;  // section "midsurface" (docs/midsurface.md)
  param::VolumeParamOptions volume;     // section "decomposition" (docs/decomposition.md)
  spline::BlockFitOptions fit;          // section "fit"
};

// Reads and validates a case file. Unknown keys, wrong types, missing files
// and inconsistent counts throw Error(BadInput) naming the key.
CaseFile read_case_file(const std::string& path);

// Serialises a case as JSON text (paths written relative to `relative_to`).
std::string case_file_json(const CaseFile& c, const std::string& relative_to);

}  // namespace igaprep::cli
