// The solve in named steps (MFEM's layering): input checks, refinement,
// quadrature tables, degrees of freedom and constraints, stiffness, loads,
// the linear solve, post-processing. Each step lives in its own file.
#include "igaprep/iga_check/elasticity_solve.h"

#include <chrono>

#include "elasticity_dofs.h"
#include "elasticity_input.h"
#include "elasticity_linear_solve.h"
#include "elasticity_loads.h"
#include "elasticity_postprocess.h"
#include "elasticity_prescribed.h"
#include "elasticity_stiffness.h"
#include "elasticity_tables.h"
#include "igaprep/iga_check/elasticity_refine.h"
#include "igaprep/spline/multipatch_topology.h"

namespace igaprep::iga_check {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

}  // namespace

ElasticitySolution solve_elasticity(const spline::MultiPatch& input, const ElasticityProblem& problem,
                                    const ElasticityOptions& options) {
  const std::vector<LameParameters> lame = detail::check_elasticity_input(input, problem, options);
  ElasticitySolution sol;
  ElasticityReport& rep = sol.report;
  const auto t_assembly = Clock::now();
  sol.model = refine_for_analysis(input, options.elevate, options.refine);
  const spline::MultiPatch& mp = sol.model;
  const std::vector<detail::PatchTables> tables = detail::quadrature_tables(mp, options.extra_quadrature);
  spline::GlobalNumbering numbering = spline::global_numbering(mp);

  const auto t_projection = Clock::now();
  const detail::PrescribedValues prescribed =
      detail::project_prescribed(mp, numbering, tables, problem.prescribed);
  rep.projection_seconds = seconds_since(t_projection);
  const detail::ElasticityDofs dofs = detail::constrain_dofs(mp, std::move(numbering), prescribed, problem.fixed);
  rep.unknowns = dofs.unknowns;
  rep.fixed_dofs = static_cast<long long>(dofs.constrained.size()) - dofs.unknowns;
  rep.prescribed_dofs = dofs.prescribed;

  const detail::StiffnessSystem system = detail::assemble_stiffness(mp, tables, dofs, lame, rep, options.progress);
  Eigen::VectorXd F = detail::assemble_loads(mp, tables, dofs, problem);
  F -= system.lifting;
  rep.assembly_seconds = seconds_since(t_assembly);

  const auto t_solve = Clock::now();
  const Eigen::VectorXd u = detail::solve_linear_system(system.matrix, F, detail::nodal_layout(mp, dofs), options, rep);
  rep.solve_seconds = seconds_since(t_solve);
  detail::store_solution(u, dofs, system, sol.model, rep);
  return sol;
}

}  // namespace igaprep::iga_check
