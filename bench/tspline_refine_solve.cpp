// Benchmarks of trivariate T-splines (issue 18), a plain main:
//  1. conversion of a model (igaprep HDF5, e.g. a run's model.h5 of ring2)
//     to a T-spline and one local refinement pass: every element whose
//     centre lies in the part of the bounding box with x above its middle
//     (a half of the model) split once in each direction, with the closure
//     and the interfaces, then the extraction form;
//  2. assembly speed of the extraction-form solve against the multipatch
//     solve on the same cantilever box (one cubic patch, n^3 elements).
// Usage: bench_tspline_refine_solve MODEL.h5 [n]
#include <Eigen/Geometry>
#include <chrono>
#include <cstdio>
#include <exception>
#include <string>

#include "igaprep/core/allocator.h"
#include "igaprep/export/hdf5_model.h"
#include "igaprep/iga_check/elasticity_solve.h"
#include "igaprep/iga_check/extraction_solve.h"
#include "igaprep/spline/tspline_model.h"
#include "bench_models.h"
#include "peak_memory.h"

using namespace igaprep;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

void refine_model(const std::string& file) {
  const spline::MultiPatch mp = exporter::read_hdf5_model(file);
  Eigen::AlignedBox3d box;
  for (const spline::Patch& p : mp.patches)
    for (Eigen::Index i = 0; i < p.control_points.rows(); ++i) box.extend(Eigen::Vector3d(p.control_points.row(i).transpose()));
  Eigen::AlignedBox3d half = box;
  half.min().x() = box.center().x();
  auto start = std::chrono::steady_clock::now();
  const spline::ExtractionModel plain = spline::extraction_model(spline::tspline_model(mp));
  const double convert = seconds_since(start);
  start = std::chrono::steady_clock::now();
  spline::TSplineModel t = spline::tspline_model(mp);
  const int splits = spline::refine_in_region(t, half, 1);
  const double refine = seconds_since(start);
  start = std::chrono::steady_clock::now();
  const spline::ExtractionModel refined = spline::extraction_model(t);
  const double extract = seconds_since(start);
  std::printf("%s: conversion %.2f s (%d functions, %zu elements); refinement pass %.2f s (%d splits) + extraction %.2f s "
              "(%d functions, %zu elements); VmHWM %.0f MiB\n",
              file.c_str(), convert, plain.function_count(), plain.elements.size(), refine, splits, extract,
              refined.function_count(), refined.elements.size(), peak_memory_kib() / 1024.0);
}

void assembly_speed(int n) {
  const spline::MultiPatch mp = cantilever_box(3, n);
  iga_check::ElasticityProblem problem;
  problem.fixed = {{"clamp", {{true, true, true}}}};
  problem.tractions = {{"tip", Eigen::Vector3d(0, 0, -1e6)}};
  const iga_check::ElasticitySolution a = iga_check::solve_elasticity(mp, problem);
  const iga_check::ExtractionSolution b = iga_check::solve_elasticity(spline::extraction_model(spline::tspline_model(mp)), problem);
  std::printf("cantilever n=%d: %lld unknowns; assembly multipatch %.2f s (%.3g unknowns/s), extraction %.2f s (%.3g unknowns/s), "
              "ratio %.2f; strain energy %.10g / %.10g\n",
              n, a.report.unknowns, a.report.assembly_seconds, a.report.unknowns / a.report.assembly_seconds, b.report.assembly_seconds,
              b.report.unknowns / b.report.assembly_seconds, b.report.assembly_seconds / a.report.assembly_seconds, a.report.strain_energy,
              b.report.strain_energy);
}

}  // namespace

int main(int argc, char** argv) {
  keep_freed_memory_for_reuse();
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s MODEL.h5 [n]\n", argv[0]);
    return 1;
  }
  try {
    refine_model(argv[1]);
    assembly_speed(argc > 2 ? std::stoi(argv[2]) : 10);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
