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
#include <string>

#include "igaprep/core/allocator.h"
#include "igaprep/export/hdf5_model.h"
#include "igaprep/iga_check/elasticity_solve.h"
#include "igaprep/iga_check/extraction_solve.h"
#include "igaprep/spline/knot_vector.h"
#include "igaprep/spline/tspline_model.h"
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

spline::MultiPatch cantilever(int n) {
  spline::Patch pa;
  pa.degrees = {3, 3, 3};
  std::vector<double> br(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) br[static_cast<std::size_t>(i)] = double(i) / n;
  std::array<std::vector<double>, 3> g;
  for (std::size_t d = 0; d < 3; ++d) {
    pa.knots[d] = spline::knot_vector_from_breaks(br, 3);
    g[d] = spline::greville_abscissae(pa.knots[d], 3);
  }
  pa.control_points.resize(pa.count(0) * pa.count(1) * pa.count(2), 3);
  for (int k = 0; k < pa.count(2); ++k)
    for (int j = 0; j < pa.count(1); ++j)
      for (int i = 0; i < pa.count(0); ++i) pa.control_points.row(pa.index(i, j, k)) << 4 * g[0][static_cast<std::size_t>(i)], g[1][static_cast<std::size_t>(j)], g[2][static_cast<std::size_t>(k)];
  spline::MultiPatch mp;
  mp.patches = {pa};
  mp.materials = {{"steel", 210e9, 0.3}};
  mp.labels = {"clamp", "tip"};
  mp.boundaries = {{0, 1, 0}, {0, 2, 1}};
  return mp;
}

void assembly_speed(int n) {
  const spline::MultiPatch mp = cantilever(n);
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
  refine_model(argv[1]);
  assembly_speed(argc > 2 ? std::stoi(argv[2]) : 10);
  return 0;
}
