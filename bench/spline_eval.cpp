// Evaluation throughput of B-spline / NURBS volumes: single points (random
// parameters) and tensor grids, points only and with Jacobians.
// Run: build-<name>/bench/bench_spline_eval
#include <benchmark/benchmark.h>

#include <random>

#include "igaprep/spline/spline.h"

using namespace igaprep::spline;

namespace {
Patch make_patch(int p, int n, bool rational) {
  Patch P;
  P.degrees = {{p, p, p}};
  for (int d = 0; d < 3; ++d) P.knots[d] = uniform_knot_vector(p, n);
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> R(-0.05, 0.05), W(0.5, 2.0);
  const auto g = greville_abscissae(P.knots[0], p);
  P.control_points.resize(n * n * n, 3);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) P.control_points.row(P.index(i, j, k)) << g[i] + R(rng), g[j] + R(rng), g[k] + R(rng);
  if (rational) {
    P.weights.resize(n * n * n);
    for (int i = 0; i < n * n * n; ++i) P.weights[i] = W(rng);
  }
  return P;
}

void BM_SinglePoint(benchmark::State& st) {
  const Patch P = make_patch(static_cast<int>(st.range(0)), 12, st.range(1) != 0);
  const int order = static_cast<int>(st.range(2));
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> R(0, 1);
  std::vector<Eigen::Vector3d> u(4096);
  for (auto& x : u) x = Eigen::Vector3d(R(rng), R(rng), R(rng));
  size_t i = 0;
  for (auto _ : st) {
    if (order == 0) benchmark::DoNotOptimize(evaluate_point(P, u[i++ & 4095]));
    else benchmark::DoNotOptimize(evaluate_jacobian(P, u[i++ & 4095]));
  }
  st.counters["points/s"] = benchmark::Counter(static_cast<double>(st.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SinglePoint)->ArgNames({"p", "rational", "order"})
    ->Args({2, 0, 0})->Args({3, 0, 0})->Args({3, 1, 0})->Args({2, 0, 1})->Args({3, 0, 1})->Args({3, 1, 1});

void BM_Grid(benchmark::State& st) {
  const Patch P = make_patch(static_cast<int>(st.range(0)), 12, st.range(1) != 0);
  const int order = static_cast<int>(st.range(2));
  const int m = 64;
  std::array<std::vector<double>, 3> g;
  for (int d = 0; d < 3; ++d)
    for (int i = 0; i < m; ++i) g[d].push_back((i + 0.5) / m);
  const GridBasis basis = grid_basis(P, g, order);  // analysed once
  for (auto _ : st) {
    if (order == 0) benchmark::DoNotOptimize(evaluate_grid_points(P, basis));
    else benchmark::DoNotOptimize(evaluate_grid(P, basis));
  }
  st.counters["points/s"] =
      benchmark::Counter(static_cast<double>(st.iterations()) * m * m * m, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Grid)->ArgNames({"p", "rational", "order"})
    ->Args({2, 0, 0})->Args({3, 0, 0})->Args({3, 1, 0})->Args({2, 0, 1})->Args({3, 0, 1})->Args({3, 1, 1})
    ->Unit(benchmark::kMillisecond);
}  // namespace

BENCHMARK_MAIN();
