#pragma once
// The w-field of the decomposition (seed paper, section 5.1): harmonic on H,
// w = 0 on T1, w = (i - 1)/n on Ti (i = 2..n), w = 1 on the base surface M.
// Its gradient carries M's boundary and corners out to T1 (the streamlines of
// volume_param.h).
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "igaprep/param/decomposition_mesh.h"
#include "igaprep/param/harmonic_field.h"
#include "igaprep/param/maximum_principle.h"

namespace igaprep::param {

struct WField {
  Eigen::VectorXd w;                       // #H.V
  std::vector<char> is_dirichlet;          // #H.V: on T1..Tn or M
  Eigen::SparseMatrix<double> K;           // the stiffness matrix of H
  std::vector<LocalExtremum> extrema;      // interior (free-vertex) strict local extrema of the solve
  int flattened = 0;                       // values changed to remove them (flatten_interior_extrema)
  double min_value = 0.0, max_value = 0.0;  // over all vertices
  int num_free = 0;
  int cg_iterations = 0;                   // 0 for a direct solve
};

// Dirichlet value of surface k (0-based, k = n for M).
inline double w_boundary_value(int k, int n) { return k >= n ? 1.0 : static_cast<double>(k) / n; }

// CG to a relative residual of 1e-12 (the default 1e-10 leaves w visibly
// off at the 1e-9 level that the checks look at).
HarmonicSolverOptions w_field_default_options();

// Inputs: H (decomposition_mesh), solver options (its level sets become patch faces). Output: the field with its maximum-principle check
// (find_interior_extrema, tolerance 1e-9 of the range); those extrema are
// then flattened (w at them is no longer exactly the solve's). Throws bad_input when
// H is malformed (from the solver).
WField w_field(const DecompositionMesh& H, HarmonicSolverOptions options = w_field_default_options());

}  // namespace igaprep::param
