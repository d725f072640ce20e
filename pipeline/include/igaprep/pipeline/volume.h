#pragma once
// The decomposition, parameterization and fit stages (seed paper, sections 5
// to 7): H with M embedded (TetGen's second and last run), the w-field, M's
// layout; the sampled hex blocks (strategy 2 or 1); their conforming
// B-spline fit with labelled sides and repaired Jacobians.
#include "igaprep/iga_check/report.h"
#include "igaprep/param/base_layout.h"
#include "igaprep/param/base_surface.h"
#include "igaprep/param/decomposition_mesh.h"
#include "igaprep/param/volume_param.h"
#include "igaprep/param/w_field.h"
#include "igaprep/pipeline/case.h"
#include "igaprep/pipeline/observer.h"
#include "igaprep/pipeline/surfaces.h"
#include "igaprep/spline/multipatch.h"
#include "igaprep/spline/optimize_jacobian.h"

namespace igaprep::pipeline {

struct Decomposition {
  param::DecompositionMesh H;  // T1..Tn with M embedded
  param::WField w;             // harmonic w on H
  param::BaseLayout layout;    // M's rectangles and boundary segments
  double diagonal = 0.0;       // of H's bounding box: the scale of the stages' tolerances
};

struct Fit {
  spline::MultiPatch model;  // labels = the case's surface labels, materials = the case's
  int stitched = 0;          // side control points made identical by stitching
  double max_stitch = 0.0;   // the largest such move
  int unmatched_sides = 0;   // sides neither on an interface nor labelled (0 for a valid model)
  std::vector<spline::SurfaceFitResult> surface_fits;  // per input surface, what fit_model_surface did (empty when off)
  spline::JacobianOptimizationResult jacobians;  // what optimize_jacobians did (all zero when off)
};

// Intermediates offered: decomposition_w (H with w).
Decomposition decompose_stage(const Case& c, const Surfaces& surfaces, const param::BaseSurface& base,
                              Observer& observer);

// Its summary's details name what the blocks leave out of the input surfaces
// (block_coverage.h): material volumes and uncovered parts beyond the case's
// check limits. Intermediates offered: decomposition_samples,
// decomposition_blocks, decomposition_blocks_faces.
param::VolumeParam param_stage(const Case& c, const Surfaces& surfaces, const Decomposition& d, Observer& observer);

// The blocks fitted, stitched, their interfaces found and sides labelled;
// then the faces on each input surface fitted to it (fit_model_surface,
// the moves carried inside) when the case's surface_iterations are above 0;
// then optimize_jacobians when the case's target is above 0.
Fit fit_stage(const Case& c, const Surfaces& surfaces, const Decomposition& d, const param::VolumeParam& vp,
              Observer& observer);

// The points (patch, its parameters) where a check's certificate found det
// J negative.
std::vector<std::pair<int, Eigen::Vector3d>> negative_points(const iga_check::CheckReport& report);

// The Jacobian repair's last pass once more, with `witnesses` (points
// where det J was found negative, negative_points; they lie between the
// repair's own samples) among its samples (spline::repair_at_witnesses): on
// `mp`, a fitted model of `vp`'s blocks, with the case's repair options.
spline::JacobianOptimizationResult repair_at_negative_points(
    const Case& c, const Decomposition& d, const param::VolumeParam& vp, spline::MultiPatch& mp,
    const std::vector<std::pair<int, Eigen::Vector3d>>& witnesses, Observer& observer);

}  // namespace igaprep::pipeline
