#pragma once
// What to solve: the loads, constraints and solver options of a small-strain
// isotropic linear-elasticity problem on a spline::MultiPatch, and the figures
// a solve reports. Plain structs; solve_elasticity (elasticity_solve.h) acts on them.
#include <Eigen/Core>
#include <array>
#include <functional>
#include <optional>

#include "igaprep/core/progress.h"
#include <string>
#include <vector>

namespace igaprep::iga_check {

// Zero displacement of the chosen components on every side labelled `label`.
struct FixedSide {
  std::string label;
  std::array<bool, 3> components{{true, true, true}};  // x, y, z
};

// Prescribed (generally non-zero) displacement u(x) on every side labelled
// `label`. The constrained coefficients (the control points of all prescribed
// sides) take the values of the L2 projection of the prescribed functions onto
// the spline space traced on those sides, assembled globally so a coefficient
// shared by several sides or patches gets one value (docs/elasticity-solver.md).
// A component that a FixedSide also constrains is zero.
struct PrescribedSide {
  std::string label;
  std::function<Eigen::Vector3d(const Eigen::Vector3d&)> displacement;
};

// Constant traction vector (force per area) on every side labelled `label`.
struct TractionLoad {
  std::string label;
  Eigen::Vector3d traction = Eigen::Vector3d::Zero();
};

// Pressure on every side labelled `label`: traction = -pressure * n with n the
// outward normal, so a positive pressure pushes into the solid.
struct PressureLoad {
  std::string label;
  double pressure = 0.0;
};

// A total force spread as one constant traction over every side labelled
// with one of `labels`: traction = force / (the sides' summed area), so the
// sides together carry exactly `force` (a joint load given in newtons).
struct ForceLoad {
  std::vector<std::string> labels;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
};

// The model spinning at a steady angular velocity about an axis (through
// `point` along `axis`), seen in its rotating frame: the centrifugal body
// force density * omega^2 * r per volume, r the vector from the axis to x.
struct RotationLoad {
  double density = 0.0;           // mass per volume (t/mm^3 with MPa and mm)
  double angular_velocity = 0.0;  // rad/s
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // any length but zero
  Eigen::Vector3d point = Eigen::Vector3d::Zero();

  Eigen::Vector3d body_force(const Eigen::Vector3d& x) const {
    const Eigen::Vector3d a = axis.normalized(), r = x - point;
    return density * angular_velocity * angular_velocity * (r - r.dot(a) * a);
  }
};

struct ElasticityProblem {
  std::vector<FixedSide> fixed;
  std::vector<PrescribedSide> prescribed;
  std::vector<TractionLoad> tractions;
  std::vector<PressureLoad> pressures;
  std::vector<ForceLoad> forces;
  std::optional<RotationLoad> rotation;
  Eigen::Vector3d body_force = Eigen::Vector3d::Zero();  // force per volume
  // Optional body force b(x) per volume, added to `body_force` at every
  // quadrature point (used for manufactured solutions).
  std::function<Eigen::Vector3d(const Eigen::Vector3d&)> body_force_function;
};

// Automatic: Cholesky while its factor (predicted by CHOLMOD's symbolic
// analysis) fits ElasticityOptions::direct_max_factor_bytes and the
// unknowns direct_max_unknowns, Amg otherwise (docs/elasticity-solver.md,
// "Large problems").
enum class LinearSolver { Automatic, Cholesky, ConjugateGradient, Amg };
// "auto", "cholesky", "cg" or "amg"; throws bad_input naming the choices.
LinearSolver linear_solver_named(const std::string& name);
const char* linear_solver_name(LinearSolver solver);

struct ElasticityOptions {
  int refine = 0;   // uniform h-refinement levels: each level bisects every knot span
  int elevate = 0;  // degree elevation in every direction (applied before refine)
  // Gauss points per direction: degree + 1 + extra_quadrature.
  int extra_quadrature = 0;
  LinearSolver solver = LinearSolver::Automatic;
  long long direct_max_unknowns = 200'000;  // LinearSolver::Automatic's switch to Amg (docs)
  // Automatic's other switch: the factor's values, 8 bytes an entry
  // (docs/elasticity-solver.md, "Large problems").
  double direct_max_factor_bytes = 2.0 * 1024 * 1024 * 1024;
  double cg_tolerance = 1e-8;   // relative residual for ConjugateGradient and Amg
  int cg_max_iterations = 0;    // 0: 10 * unknowns (ConjugateGradient), 1,000 (Amg)
  // Refused before any work when the refined model would have more scalar
  // unknowns than this (estimated from the knot vectors, shared control
  // points counted once per patch): memory grows faster than the unknowns.
  long long max_unknowns = 1'000'000;
  ProgressCallback progress;    // elements assembled
};

struct ElasticityReport {
  long long unknowns = 0;        // free scalar unknowns after eliminating constraints
  long long fixed_dofs = 0;      // scalar coefficients set by constraints (zero or prescribed)
  long long prescribed_dofs = 0; // of which set by PrescribedSide (L2 projection)
  long long nonzeros = 0;        // stored non-zeros of the stiffness matrix (one triangle)
  long long elements = 0;        // knot-span elements integrated
  long long quadrature_points = 0;
  double assembly_seconds = 0.0;
  double solve_seconds = 0.0;
  double projection_seconds = 0.0;  // L2 projection of prescribed displacements (in assembly_seconds)
  double strain_energy = 0.0;    // 1/2 u^T K u (all coefficients, prescribed included)
  double max_displacement = 0.0; // largest |u| over the control coefficients (see docs)
  int cg_iterations = 0;
  double cg_residual = 0.0;
  std::string solver;            // the linear solver actually used
  double factor_entries = 0.0;   // entries of CHOLMOD's factor, predicted by its analysis (0: not analysed)
};

}  // namespace igaprep::iga_check
