// igaprep tspline MODEL.h5 -o OUT.h5 [--refine-box XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX]... [--levels N]
// A multipatch model as a T-spline in Bezier-extraction form
// (igaprep-bezier-extraction, docs/hdf5-format.md); with --refine-box the
// elements whose centre lies in a box are refined locally, N times in each
// direction, keeping the model analysis-suitable (docs/tspline.md).
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
#include "igaprep/spline/extraction_model.h"
#include "igaprep/spline/tspline_model.h"

namespace igaprep::cli {

namespace {

struct TsplineArgs {
  std::string model, output;
  std::vector<std::string> boxes;
  int levels = 1;
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
  set_body(sub, [a] {
    std::vector<Eigen::AlignedBox3d> boxes;
    for (const std::string& s : a->boxes) boxes.push_back(parse_box(s));
    refuse_replacing_inputs({a->model}, {a->output});
    const spline::MultiPatch mp = exporter::read_hdf5_model(a->model);
    const spline::ExtractionModel m = refined_model(mp, boxes, a->levels);
    exporter::write_hdf5_extraction(m, a->output);
    std::cout << "tspline: " << m.function_count() << " functions, " << m.elements.size() << " elements, "
              << m.boundary_faces.size() << " labelled element faces\n"
              << "wrote " << a->output << "\n";
    return 0;
  });
}

}  // namespace igaprep::cli
