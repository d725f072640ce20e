#pragma once
// The midsurface and base-surface stages (seed paper, section 4): cut loops
// on T1, the tet mesh of the cut surfaces (TetGen's one run before H), the
// midsurface M0, M0trim with its 2D polycube (u, v), then the base surface M.
#include "igaprep/param/base_surface.h"
#include "igaprep/param/midsurface_pipeline.h"
#include "igaprep/pipeline/case.h"
#include "igaprep/pipeline/observer.h"
#include "igaprep/pipeline/surfaces.h"

namespace igaprep::pipeline {

// Intermediates offered: tetmesh, midsurface_t1_regions, midsurface_loops,
// midsurface_m0, midsurface_m0trim, midsurface_m0trim_uv, midsurface_rectangles.
param::MidsurfaceResult midsurface_stage(const Case& c, const Surfaces& surfaces, Observer& observer);

// Intermediates offered: base_surface (M with its (u, v)), base_surface_corners.
// The innermost surface (M0trim's rim) caps the inset where the solid is thin.
param::BaseSurface base_stage(const Case& c, const Surfaces& surfaces, const param::MidsurfaceResult& mid,
                              Observer& observer);

}  // namespace igaprep::pipeline
