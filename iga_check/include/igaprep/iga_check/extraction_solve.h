#pragma once
// Linear elasticity on a model in Bezier-extraction form (a T-spline, issue
// 18): the problem of elasticity_problem.h, assembled element by element
// through each element's C_e (the element's functions in its Bernstein
// polynomials), so an element's function count may vary. Fixed, prescribed
// (L2 projection on the labelled faces' traces), traction, pressure and
// force loads, body forces and rotation; no refinement or elevation here
// (refine the T-spline instead).
#include <Eigen/Core>

#include "igaprep/iga_check/elasticity_problem.h"
#include "igaprep/spline/extraction_model.h"

namespace igaprep::iga_check {

struct ExtractionSolution {
  Eigen::MatrixXd displacement;  // functions x 3: the coefficients of u
  ElasticityReport report;
};

// Throws bad_input for an unknown label, options.refine or elevate other
// than 0, or constraints that leave the model free to move (K singular).
ExtractionSolution solve_elasticity(const spline::ExtractionModel& model, const ElasticityProblem& problem,
                                    const ElasticityOptions& options = {});

// The point, u and grad u (d u_i / d x_j) at Bernstein coordinates t of an
// element, from a solution's coefficients.
struct ExtractionPointValue {
  Eigen::Vector3d x, displacement;
  Eigen::Matrix3d gradient;
};
ExtractionPointValue evaluate_solution(const spline::ExtractionModel& model, const Eigen::MatrixXd& displacement, int element,
                                       const Eigen::Vector3d& t);

}  // namespace igaprep::iga_check
