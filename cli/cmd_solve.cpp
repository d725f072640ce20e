// igaprep solve MODEL.h5 -o RESULT.h5 [--fix LABEL[:COMPONENTS]]...
// [--pressure LABEL=P]... [--traction LABEL=TX,TY,TZ]... [--force LABEL=FX,FY,FZ]...
// [--body-force FX,FY,FZ] [--rotation DENSITY,OMEGA[,AX,AY,AZ[,PX,PY,PZ]]]
// [--refine N] [--elevate K] [--solver auto|cholesky|cg|amg]: linear elasticity on the
// model (docs/elasticity-solver.md); RESULT.h5 is the refined model plus the
// displacement per patch and the root attributes strain_energy and
// max_displacement. A T-spline model (igaprep-bezier-extraction) is solved
// through its extraction operators and written back in its own format with
// the displacement per function. Bad input: error, exit 1, nothing written.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "commands.h"
#include "number_args.h"
#include "igaprep/core/atomic_file.h"
#include "igaprep/core/input_files.h"
#include "igaprep/core/text.h"
#include "igaprep/core/error.h"
#include "igaprep/export/hdf5_extraction.h"
#include "igaprep/export/hdf5_model.h"
#include "igaprep/iga_check/elasticity_solve.h"
#include "igaprep/iga_check/extraction_solve.h"

namespace igaprep::cli {

namespace {

struct SolveArgs {
  std::string model, output, body_force, rotation, solver = "auto";
  std::vector<std::string> fix, pressure, traction, force;
  int refine = 0, elevate = 0;
  long long max_unknowns = iga_check::ElasticityOptions{}.max_unknowns;
};

Eigen::Vector3d parse_vector(const std::string& s, const std::string& what) {
  const std::vector<double> v = parse_numbers(s, what);
  if (v.size() != 3) throw bad_input(what + ": expected three numbers X,Y,Z, got '" + s + "'");
  return Eigen::Vector3d(v[0], v[1], v[2]);
}

// DENSITY,OMEGA[,AX,AY,AZ[,PX,PY,PZ]]: axis z and the origin by default.
iga_check::RotationLoad parse_rotation(const std::string& s) {
  const std::vector<double> v = parse_numbers(s, "--rotation");
  if (v.size() != 2 && v.size() != 5 && v.size() != 8)
    throw bad_input("--rotation: expected DENSITY,OMEGA[,AX,AY,AZ[,PX,PY,PZ]] (2, 5 or 8 numbers), got '" + s + "'");
  iga_check::RotationLoad r;
  r.density = v[0];
  r.angular_velocity = v[1];
  if (v.size() >= 5) r.axis = Eigen::Vector3d(v[2], v[3], v[4]);
  if (v.size() == 8) r.point = Eigen::Vector3d(v[5], v[6], v[7]);
  return r;
}

// LABEL[:COMPONENTS], COMPONENTS letters of xyz or "all"; no suffix = all.
iga_check::FixedSide parse_fix(const std::string& s) {
  iga_check::FixedSide f;
  f.label = s;
  const size_t colon = s.rfind(':');
  if (colon != std::string::npos) {
    const std::string comp = s.substr(colon + 1);
    f.label = s.substr(0, colon);
    if (comp == "all" || comp.empty()) {
      f.components = {{true, true, true}};
    } else {
      f.components = {{false, false, false}};
      for (char c : comp) {
        if (c < 'x' || c > 'z')
          throw bad_input("--fix " + s + ": components must be letters of 'xyz' or 'all', got '" + comp + "'");
        f.components[c - 'x'] = true;
      }
    }
  }
  if (f.label.empty()) throw bad_input("--fix " + s + ": empty label");
  return f;
}

std::pair<std::string, std::string> split_assignment(const std::string& s, const std::string& option) {
  const size_t eq = s.rfind('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == s.size())
    throw bad_input(option + " " + s + ": expected LABEL=VALUE");
  return {s.substr(0, eq), s.substr(eq + 1)};
}

int run_solve(const SolveArgs& a) {
  refuse_replacing_inputs({a.model}, {a.output});
  iga_check::ElasticityProblem problem;
  for (const auto& s : a.fix) problem.fixed.push_back(parse_fix(s));
  for (const auto& s : a.pressure) {
    const auto [label, value] = split_assignment(s, "--pressure");
    problem.pressures.push_back({label, parse_number(value, "--pressure " + label)});
  }
  for (const auto& s : a.traction) {
    const auto [label, value] = split_assignment(s, "--traction");
    problem.tractions.push_back({label, parse_vector(value, "--traction " + label)});
  }
  for (const auto& s : a.force) {
    const auto [label, value] = split_assignment(s, "--force");
    problem.forces.push_back({{label}, parse_vector(value, "--force " + label)});
  }
  if (!a.body_force.empty()) problem.body_force = parse_vector(a.body_force, "--body-force");
  if (!a.rotation.empty()) problem.rotation = parse_rotation(a.rotation);
  iga_check::ElasticityOptions options;
  options.refine = a.refine;
  options.elevate = a.elevate;
  options.max_unknowns = a.max_unknowns;
  options.solver = iga_check::linear_solver_named(a.solver);
  if (problem.fixed.empty())
    throw bad_input("no constraints: give --fix LABEL[:COMPONENTS] so that no rigid-body motion is left free");

  const bool extraction = exporter::is_hdf5_extraction(a.model);
  if (extraction && (a.refine != 0 || a.elevate != 0))
    throw bad_input("--refine and --elevate are for multipatch models; refine a T-spline with igaprep tspline --refine-box");
  // The output's folder is made and tried before the solve, not after it.
  create_output_folder(std::filesystem::path(a.output).parent_path().string().empty()
                           ? "."
                           : std::filesystem::path(a.output).parent_path().string());
  AtomicPath output(a.output);
  iga_check::ElasticityReport r;
  if (extraction) {
    // A T-spline (Bezier-extraction form): solved through its C_e, written back with the displacement per function.
    spline::ExtractionModel model = exporter::read_hdf5_extraction(a.model);
    const iga_check::ExtractionSolution sol = iga_check::solve_elasticity(model, problem, options);
    model.displacement = sol.displacement;
    model.has_solution = true;
    model.strain_energy = sol.report.strain_energy;
    model.max_displacement = sol.report.max_displacement;
    exporter::write_hdf5_extraction(model, a.output);  // atomic itself; `output` only tried the folder
    r = sol.report;
  } else {
    const iga_check::ElasticitySolution sol = iga_check::solve_elasticity(exporter::read_hdf5_model(a.model), problem, options);
    exporter::write_hdf5_model(sol.model, output);
    output.commit();
    r = sol.report;
  }

  std::printf("solve: %lld unknowns (%lld fixed), %lld non-zeros, %lld elements, %lld quadrature points\n",
              r.unknowns, r.fixed_dofs, r.nonzeros, r.elements, r.quadrature_points);
  std::string how = r.solver;
  if (r.cg_iterations > 0) how += ", " + std::to_string(r.cg_iterations) + " iterations";
  if (r.factor_entries > 0.0)
    how += text(r.solver == "cholmod" ? ", factor of %.3g entries" : "; CHOLMOD's factor would hold %.3g entries",
                r.factor_entries);
  std::printf("solve: assembly %.3f s, solve %.3f s (%s)\n", r.assembly_seconds, r.solve_seconds, how.c_str());
  std::printf("solve: strain energy %.10g, max displacement %.10g\n", r.strain_energy, r.max_displacement);
  std::printf("solve: wrote %s\n", a.output.c_str());
  return 0;
}

}  // namespace

void add_solve_command(CLI::App& app) {
  auto* sub = app.add_subcommand("solve", "Linear-elasticity IGA solve of a model (docs/elasticity-solver.md)");
  auto args = std::make_shared<SolveArgs>();
  sub->add_option("model", args->model, "Model file (HDF5, docs/hdf5-format.md)")->required()->check(CLI::ExistingFile);
  sub->add_option("-o,--output", args->output, "Result file: the refined model with displacement (HDF5; a T-spline stays a T-spline)")->required();
  sub->add_option("--fix", args->fix, "Zero displacement on a labelled boundary: LABEL[:COMPONENTS], e.g. base:xyz, sym:x")
      ->allow_extra_args(false);
  sub->add_option("--pressure", args->pressure, "Pressure on a labelled boundary: LABEL=P (positive pushes in)")
      ->allow_extra_args(false);
  sub->add_option("--traction", args->traction, "Constant traction on a labelled boundary: LABEL=TX,TY,TZ")
      ->allow_extra_args(false);
  sub->add_option("--force", args->force, "Total force spread over a labelled boundary: LABEL=FX,FY,FZ");
  sub->add_option("--body-force", args->body_force, "Body force per volume: FX,FY,FZ");
  sub->add_option("--rotation", args->rotation,
                  "Centrifugal load of a steady spin: DENSITY,OMEGA[,AX,AY,AZ[,PX,PY,PZ]] (axis z through the origin by default)");
  sub->add_option("--refine", args->refine, "Uniform h-refinement levels (each bisects every knot span)")
      ->check(CLI::Range(0, 10));
  sub->add_option("--elevate", args->elevate, "Degree elevation in every direction")->check(CLI::Range(0, 10));
  sub->add_option("--max-unknowns", args->max_unknowns,
                  "Refuse a refined model with more unknowns than this (estimated first; default 1000000)")
      ->check(positive_number());
  sub->add_option("--solver", args->solver, "Linear solver: auto (cholesky up to 200,000 unknowns and a factor of 2 GiB, amg above), cholesky (CHOLMOD when present), cg (incomplete Cholesky) or amg (BoomerAMG)");
  set_body(sub, [args] { return run_solve(*args); });
}

}  // namespace igaprep::cli
