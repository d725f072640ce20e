#pragma once
// Trivariate T-spline models (issue 18): a conforming multipatch of odd
// degree with a T-mesh per patch, locally refined so that it stays
// analysis-suitable, and its Bezier-extraction form. The geometry is the
// multipatch's at every step: refinement only enlarges the space (nested
// spaces), and the new control points are the exact least-squares
// representation of the old geometry, per Bezier element.
#include <Eigen/Geometry>
#include <utility>
#include <vector>

#include "igaprep/spline/extraction_model.h"
#include "igaprep/spline/multipatch.h"
#include "igaprep/spline/tmesh.h"

namespace igaprep::spline {

struct TSplineModel {
  MultiPatch base;            // geometry, sides, interfaces, labels, materials
  std::vector<TMesh> meshes;  // one per patch
};

// The tensor T-meshes of a model, split across split_directions in turn
// (TMesh; every patch alike). Throws bad_input for an even degree or an
// interior knot of multiplicity above 1 (local refinement is defined here
// for odd degrees on simple knots), or for a model that is not valid.
TSplineModel tspline_model(const MultiPatch& mp, const std::vector<int>& split_directions = {0, 1, 2});

// Splits each listed (patch, box) once, each with the closure that keeps its
// mesh analysis-suitable; then refines the neighbours across interfaces
// until the two meshes on every interface are the same, so that the
// functions on it are shared (C0). Throws bad_input for an index out of range.
void refine_boxes(TSplineModel& model, const std::vector<std::pair<int, int>>& boxes);

// Refines every box whose centre (its parameter midpoint mapped by the
// geometry) lies in `region` until it is 2^levels times finer than its
// patch's elements in each split direction (level levels x their count),
// with the closure and the interfaces as refine_boxes. Returns the number
// of boxes split.
int refine_in_region(TSplineModel& model, const Eigen::AlignedBox3d& region, int levels);

// Boxes over all patches.
long tmesh_box_count(const TSplineModel& model);

// The model in Bezier-extraction form: its functions (shared across
// interfaces), control points and weights from nestedness, and per Bezier
// element (a box of the mesh, split where a function's knot runs through
// it) the functions and C_e. Throws internal_error when a mesh is not dual
// compatible or the old geometry is not reproduced (to 1e-10 of the
// diagonal): neither may happen after refine_boxes.
ExtractionModel extraction_model(const TSplineModel& model);

}  // namespace igaprep::spline
