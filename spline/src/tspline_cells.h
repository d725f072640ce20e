#pragma once
// Internal to the T-spline model's extraction: the Bezier elements of one
// patch's T-mesh with their functions, their C_e as 1-D vectors per
// function, and the functions' control points.
#include <Eigen/Core>
#include <vector>

#include "igaprep/spline/extraction_model.h"
#include "igaprep/spline/multipatch.h"
#include "igaprep/spline/tmesh.h"
#include "igaprep/spline/tspline_functions.h"

namespace igaprep::spline::detail {

// FNV-1a over a vector of integers (of any integer type).
struct IntsHash {
  template <typename Int>
  std::size_t operator()(const std::vector<Int>& k) const {
    std::size_t h = 1469598103934665603ull;
    for (const Int x : k) h = (h ^ static_cast<std::size_t>(x)) * 1099511628211ull;
    return h;
  }
};

struct PatchCells {
  std::vector<ExtractionElement> elements;      // extraction: index into operator_keys
  std::vector<std::vector<int>> operator_keys;  // per distinct C_e: its functions' 1-D vectors (u, v, w ids)
  std::vector<Eigen::VectorXd> vectors_1d;      // those 1-D vectors
  std::vector<TFunction> functions;         // of the patch
  Eigen::MatrixXd homogeneous;              // per function (x w, y w, z w, w)
};

// The patch's cells: through its own extraction when its mesh is the tensor
// grid, else the refined mesh's (throws internal_error for a mesh that is
// not dual compatible).
PatchCells patch_cells(const Patch& patch, const TMesh& mesh, int patch_index);

// Nestedness, checked at every cell's centre against the patch: throws
// internal_error beyond `tolerance`. (A patch whose mesh is not refined is
// its own extraction and needs no check.)
void check_reproduces_geometry(const Patch& patch, const PatchCells& cells, int patch_index, double tolerance);

}  // namespace igaprep::spline::detail
