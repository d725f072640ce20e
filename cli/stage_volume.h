#pragma once
// The decomposition, parameterization and fit stages (seed paper, sections 5
// to 7): H with M embedded, the w-field, M's layout, the sampled blocks of
// strategy 2 and their conforming B-spline fit. One summary line per stage.
#include <string>

#include "case_file.h"
#include "case_surfaces.h"
#include "igaprep/param/midsurface_pipeline.h"
#include "igaprep/param/volume_param.h"
#include "igaprep/spline/block_fit.h"
#include "igaprep/spline/multipatch.h"
#include "igaprep/spline/optimize_jacobian.h"

namespace igaprep::cli {

struct VolumeStageResult {
  spline::MultiPatch model;
  int stitched = 0;          // side control points made identical by stitching
  double max_stitch = 0.0;   // the largest such move
  int unmatched_sides = 0;   // sides neither on an interface nor labelled (0 for a valid model)
  spline::JacobianOptimizationResult jacobians;  // what optimize_jacobians did (all zero when off)
  double decompose_seconds = 0.0, param_seconds = 0.0, fit_seconds = 0.0;
};

// Inputs: the case, its surfaces, the midsurface stage's result, output
// folder, whether to write intermediate VTU files. Output: the fitted model
// (labels = the case's surface labels, materials = the case's materials).
VolumeStageResult run_volume_stages(const CaseFile& c, const CaseSurfaces& surfaces,
                                    const param::MidsurfaceResult& mid, const std::string& dir, bool keep_intermediate);

}  // namespace igaprep::cli
