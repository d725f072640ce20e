// Data reduction of a model file (docs/spline.md, "Data reduction"): the
// knot removal alone (spline::reduce_model, no certificate) and the reduce
// stage with its certificate guard, at a tolerance relative to the model's
// diagonal. The model is one a run wrote, e.g. ring2 at 12 elements:
//   build/bin/igaprep run CASE.json  (with "fit": {"elements": 12})
//   build/bench/bench_pipeline_reduce OUT/model.h5 [RELATIVE_TOLERANCE]
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "igaprep/export/hdf5_model.h"
#include "igaprep/iga_check/fidelity.h"
#include "igaprep/pipeline/reduce.h"

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s MODEL.h5 [RELATIVE_TOLERANCE (default 0.001)]\n", argv[0]);
    return 1;
  }
  using namespace igaprep;
  const spline::MultiPatch mp = exporter::read_hdf5_model(argv[1]);
  const double relative = argc > 2 ? std::atof(argv[2]) : 1e-3;
  spline::ModelReductionOptions o;
  o.tolerance = relative * iga_check::model_diagonal(mp);

  auto t0 = std::chrono::steady_clock::now();
  const spline::ModelReduction alone = spline::reduce_model(mp, o);
  const double knot_removal = seconds_since(t0);
  std::printf("knot removal alone: %.2f s; control points %ld -> %ld, elements %ld -> %ld, bound %.3g, measured %.3g\n",
              knot_removal, alone.control_points_before, alone.control_points_after, alone.elements_before,
              alone.elements_after, alone.bound, alone.measured);

  t0 = std::chrono::steady_clock::now();
  const iga_check::CheckReport before = iga_check::build_check_report(mp, {});
  const double check = seconds_since(t0);
  pipeline::Observer quiet;
  pipeline::ReduceSettings s;
  s.relative_tolerance = relative;
  const pipeline::Reduction r = pipeline::reduce_stage(mp, s, before, {}, quiet);
  std::printf("check of the model: %.2f s; reduce stage (with the certificate guard): %.2f s; control points %ld -> "
              "%ld, %d removals undone\n",
              check, r.figures.seconds, r.figures.control_points_before, r.figures.control_points_after,
              r.figures.removals_undone);
  return 0;
}
