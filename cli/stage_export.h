#pragma once
// The export stage of `igaprep run`: OUTDIR/model.h5, then the formats the
// case's "export" key asks for (gismo, mfem, vtu, bext) with the same base
// name (OUTDIR/model.xml, ...), as `igaprep export model.h5 -o OUTDIR/model`
// would write them.
#include <string>
#include <vector>

#include "igaprep/spline/multipatch.h"

namespace igaprep::cli {

struct ExportStageResult {
  std::vector<std::string> written;  // paths: model.h5 first, then in the order asked
  double seconds = 0.0;
};

// Inputs: the model, format names (case key "export"; "hdf5" adds nothing:
// model.h5 is always written), the output folder (created if needed).
// Output: the files written. Prints one summary line.
ExportStageResult run_export_stage(const spline::MultiPatch& model, const std::vector<std::string>& formats,
                                   const std::string& dir);

}  // namespace igaprep::cli
