#pragma once
// The midsurface stage (seed paper, section 4): cut loops, M0, M0trim with
// its 2D polycube, base surface M; a summary on stdout and VTU files in dir.
#include <string>

#include "case_file.h"
#include "case_surfaces.h"
#include "igaprep/param/midsurface_pipeline.h"

namespace igaprep::cli {

param::MidsurfaceResult run_midsurface_stage(const CaseFile& c, const CaseSurfaces& surfaces, const std::string& dir);

}  // namespace igaprep::cli
