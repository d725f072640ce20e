#pragma once
// Galerkin isogeometric analysis of small-strain isotropic linear elasticity
// on a multipatch B-spline/NURBS model (docs/elasticity-solver.md).
#include "igaprep/iga_check/elasticity_problem.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::iga_check {

struct ElasticitySolution {
  spline::MultiPatch model;  // the refined model; every patch carries `displacement`,
                             // has_solution, strain_energy and max_displacement are set
  ElasticityReport report;
};

// Inputs: a valid, conforming model (patches coupled C0 through the global
// numbering of spline::global_numbering), one material per patch; the
// problem (constraints and loads on labelled boundary sides); options
// (refinement, quadrature, linear solver).
// Output: the solution and its figures.
// Throws bad_input for an unknown label, a label that names no boundary side,
// an invalid material (E <= 0, nu outside (-1, 0.5)), constraints that leave a
// rigid-body motion free (per connected part of the model), a singular
// stiffness, or a model whose Jacobian vanishes or changes sign in a patch.
ElasticitySolution solve_elasticity(const spline::MultiPatch& model, const ElasticityProblem& problem,
                                    const ElasticityOptions& options = {});

}  // namespace igaprep::iga_check
