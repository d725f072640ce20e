// igaprep tspline MODEL.h5 -o OUT.h5 [--refine-box XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX]... [--levels N]
//                                    [--surface FILE... --tolerance T [--rounds N]]
// A multipatch model as a T-spline in Bezier-extraction form
// (igaprep-bezier-extraction, docs/hdf5-format.md); with --refine-box the
// elements whose centre lies in a box are refined locally, N times in each
// direction, keeping the model analysis-suitable; with --surface and
// --tolerance its faces are fitted to the surfaces and refined where they
// stay farther than T (docs/tspline.md).
#include <Eigen/Geometry>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "number_args.h"
#include "igaprep/core/error.h"
#include "igaprep/core/input_files.h"
#include "igaprep/export/hdf5_extraction.h"
#include "igaprep/export/hdf5_model.h"
#include "igaprep/iga_check/fidelity.h"
#include "igaprep/iga_check/tspline_surface_fit.h"
#include "igaprep/mesh/read_surface.h"
#include "igaprep/spline/extraction_model.h"
#include "igaprep/spline/tspline_model.h"

namespace igaprep::cli {

namespace {

struct TsplineArgs {
  std::string model, output;
  std::vector<std::string> boxes, surfaces;
  int levels = 1;
  double tolerance = 0.0;
  int rounds = spline::TSplineFitOptions{}.max_rounds;
};

Eigen::AlignedBox3d parse_box(const std::string& s) {
  const std::vector<double> v = parse_numbers(s, "--refine-box");
  if (v.size() != 6) throw bad_input("--refine-box: expected XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX, got '" + s + "'");
  const Eigen::Vector3d lo(v[0], v[1], v[2]), hi(v[3], v[4], v[5]);
  if (!(lo.array() <= hi.array()).all()) throw bad_input("--refine-box: a minimum above its maximum in '" + s + "'");
  return Eigen::AlignedBox3d(lo, hi);
}

spline::ExtractionModel refined_model(const spline::MultiPatch& mp, const std::vector<Eigen::AlignedBox3d>& boxes, int levels) {
  if (boxes.empty()) return spline::extraction_model(mp);
  spline::TSplineModel t = spline::tspline_model(mp);
  const long before = spline::tmesh_box_count(t);
  int split = 0;
  for (const Eigen::AlignedBox3d& box : boxes) split += spline::refine_in_region(t, box, levels);
  std::cout << "refine: " << split << " splits (" << before << " -> " << spline::tmesh_box_count(t)
            << " boxes), analysis-suitable\n";
  return spline::extraction_model(t);
}

void print_fidelity(const char* what, const spline::ExtractionModel& m, const std::vector<mesh::TriMesh>& surfaces, double diagonal) {
  for (const iga_check::SurfaceFidelity& f : iga_check::fidelity(m, surfaces, diagonal))
    std::cout << "fidelity " << what << ": surface " << f.surface << " (" << f.label << "): largest distance model to surface "
              << f.spline_to_mesh.max << " (" << 100.0 * f.spline_to_mesh.max_relative << " % of the diagonal), surface to model "
              << f.mesh_to_spline.max << " (" << 100.0 * f.mesh_to_spline.max_relative << " %)\n";
}

spline::ExtractionModel fitted_model(const spline::MultiPatch& mp, const TsplineArgs& a) {
  std::vector<mesh::TriMesh> surfaces;
  for (const std::string& f : a.surfaces) surfaces.push_back(mesh::read_surface(f));
  const double diagonal = iga_check::model_diagonal(mp);
  print_fidelity("before", spline::extraction_model(mp), surfaces, diagonal);
  spline::TSplineModel t = spline::tspline_model(mp);
  spline::TSplineFitOptions options;
  options.tolerance = a.tolerance;
  options.max_rounds = a.rounds;
  const iga_check::TSplineSurfaceFitResult fit = iga_check::fit_tspline_to_surfaces(t, surfaces, options);
  const spline::TSplineFitResult& r = fit.fit;
  for (std::size_t k = 0; k < r.rounds.size(); ++k)
    std::cout << "round " << k << ": " << r.rounds[k].functions << " functions, " << r.rounds[k].elements
              << " elements, largest pair distance " << r.rounds[k].max_distance << ", " << r.rounds[k].elements_over
              << " elements over the tolerance, " << r.rounds[k].boxes_refined << " boxes refined\n";
  std::cout << "Jacobian repair: " << fit.repair.uncertified_before << " elements not certified after the fit, "
            << fit.repair.uncertified_after << " after " << fit.repair.steps << " halvings of the moves of "
            << fit.repair.functions_backed_off << " functions\n";
  print_fidelity("after", r.model, surfaces, diagonal);
  if (!r.reached) std::cout << "tolerance " << a.tolerance << " not reached in " << a.rounds << " rounds\n";
  return r.model;
}

}  // namespace

void add_tspline_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "tspline", "Write an igaprep HDF5 model as a T-spline in Bezier-extraction form (igaprep-bezier-extraction), refined locally on request");
  auto a = std::make_shared<TsplineArgs>();
  sub->add_option("model", a->model, "input model, igaprep HDF5 (MODEL.h5)")->required();
  sub->add_option("-o,--output", a->output, "output file (HDF5)")->required();
  sub->add_option("--refine-box", a->boxes,
                  "refine the elements whose centre lies in this box, XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX (repeatable; odd degrees)");
  sub->add_option("--levels", a->levels, "with --refine-box: times each element is halved in every direction")
      ->check(CLI::Range(1, 6));
  auto* surface = sub->add_option("--surface", a->surfaces, "fit the faces to this input surface (repeatable, outermost first: label 0, 1, ...)");
  auto* tolerance = sub->add_option("--tolerance", a->tolerance, "with --surface: the largest face-to-surface distance to refine to (model units)")
                        ->check(positive_number());
  sub->add_option("--rounds", a->rounds, "with --surface: refinement rounds at most")->check(CLI::Range(0, 12));
  surface->needs(tolerance);
  tolerance->needs(surface);
  surface->excludes("--refine-box");
  set_body(sub, [a] {
    std::vector<Eigen::AlignedBox3d> boxes;
    for (const std::string& s : a->boxes) boxes.push_back(parse_box(s));
    std::vector<std::string> inputs = a->surfaces;
    inputs.push_back(a->model);
    refuse_replacing_inputs(inputs, {a->output});
    const spline::MultiPatch mp = exporter::read_hdf5_model(a->model);
    const spline::ExtractionModel m = a->surfaces.empty() ? refined_model(mp, boxes, a->levels) : fitted_model(mp, *a);
    exporter::write_hdf5_extraction(m, a->output);
    std::cout << "tspline: " << m.function_count() << " functions, " << m.elements.size() << " elements, "
              << m.boundary_faces.size() << " labelled element faces\n"
              << "wrote " << a->output << "\n";
    return 0;
  });
}

}  // namespace igaprep::cli
