#pragma once
// Manufactured-solution validation of any multipatch model: a smooth,
// non-polynomial displacement scaled to the model's bounding box is imposed on
// every labelled boundary side (PrescribedSide) with the matching body force,
// solved at a coarse and a fine uniform refinement, and the L2 error rate is
// measured (docs/elasticity-solver.md, "Manufactured-solution study").
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "igaprep/core/progress.h"
#include "igaprep/iga_check/elasticity_material.h"
#include "igaprep/iga_check/elasticity_problem.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::iga_check {

// u(x) = amplitude * length * g(xi), xi = (x - center) / length, each
// component of g a sum of two plane waves s(w . xi + phase) with s one of sin,
// cos, exp and |w| <= 3 (fixed coefficients; docs list them). Not polynomial
// in any direction, so no spline space reproduces it.
struct ManufacturedField {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double length = 1.0;     // the bounding-box diagonal
  double amplitude = 1e-3; // relative to length

  Eigen::Vector3d displacement(const Eigen::Vector3d& x) const;
  Eigen::Matrix3d gradient(const Eigen::Vector3d& x) const;  // (i, j) = d u_i / d x_j
  // hessians[i](j, k) = d^2 u_i / (d x_j d x_k)
  std::array<Eigen::Matrix3d, 3> hessians(const Eigen::Vector3d& x) const;
  // b = -div sigma(u) = -((lambda + mu) grad div u + mu Laplacian u).
  Eigen::Vector3d body_force(const Eigen::Vector3d& x, const LameParameters& lame) const;
};

// Inputs: the box [lo, hi] (lo <= hi, finite, not a single point); amplitude > 0
// relative to the box diagonal. Throws bad_input otherwise.
ManufacturedField manufactured_field(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                                     double amplitude = 1e-3);

struct ManufacturedOptions {
  int coarse_refine = 0;  // levels of uniform h-refinement of the coarse solve
  int fine_refine = 1;    // and of the fine solve (> coarse_refine)
  int extra_quadrature = 0;  // Gauss points beyond p + 1 in the solves (the error norms use 2 more)
  LinearSolver solver = LinearSolver::Cholesky;
  double amplitude = 1e-3;   // of the field, relative to the bounding-box diagonal
  ProgressCallback progress;  // each level's assembly, then the levels done
};

struct ManufacturedLevel {
  int refine = 0;
  long long elements = 0;        // knot-span elements of all patches
  double h = 0.0;                // largest knot span / parameter-domain length, over patches and directions
  long long unknowns = 0;        // free scalar unknowns
  long long prescribed_dofs = 0; // scalar coefficients set by the boundary projection
  double l2_error = 0.0, l2_norm = 0.0, l2_relative = 0.0;
  double energy_error = 0.0, energy_norm = 0.0, energy_relative = 0.0;  // energy norm (E = 1, nu = 0.3)
  double assembly_seconds = 0.0, solve_seconds = 0.0;
  double seconds = 0.0;          // the whole level: solve_elasticity and the error norms
  std::string solver;
};

struct ManufacturedStudy {
  ManufacturedField field;
  Eigen::Vector3d box_min = Eigen::Vector3d::Zero(), box_max = Eigen::Vector3d::Zero();  // control points' box
  std::vector<std::string> prescribed_labels;  // every label carried by a boundary side
  std::vector<ManufacturedLevel> levels;       // coarse, fine
  double h_ratio = 0.0;      // h_coarse / h_fine (2 per bisection)
  double l2_rate = 0.0;      // log(e_coarse / e_fine) / log(h_coarse / h_fine), L2 error
  double energy_rate = 0.0;  // the same for the energy error
};

// Inputs: a valid conforming model (any number of patches and materials; the
// study replaces the materials by one, E = 1, nu = 0.3) whose every patch side
// is either on an interface or a labelled boundary side; options.
// Output: the figures of both levels and the rates. The expected L2 rate of a
// degree-p model in the asymptotic range is p + 1.
// Throws bad_input for an invalid model, one without labelled boundary sides,
// a side that is neither on an interface nor labelled (it would be traction
// free, which the field is not), or bad options; errors of solve_elasticity
// pass through.
ManufacturedStudy manufactured_study(const spline::MultiPatch& model, const ManufacturedOptions& options = {});

}  // namespace igaprep::iga_check
