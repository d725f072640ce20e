// Grid-fit time for 40 x 40 x 40 coefficients (p = 2, 3), unconstrained and
// with one face fixed; scattered fit with smoothing on a smaller patch.
// Run: build-<name>/bench/bench_spline_fit
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "igaprep/spline/spline.h"

using namespace igaprep::spline;

namespace {
Eigen::RowVector3d f(double u, double v, double w) {
  return Eigen::RowVector3d(std::sin(2 * u + v), std::cos(1.5 * v) * std::exp(0.7 * w), u * v + std::sin(3 * w));
}

void BM_GridFit40(benchmark::State& st) {
  const int p = static_cast<int>(st.range(0)), n = 40, m = 2 * n;
  const bool fix_face = st.range(1) != 0;
  std::array<int, 3> deg = {{p, p, p}};
  std::array<std::vector<double>, 3> knots, params;
  for (int d = 0; d < 3; ++d) {
    knots[d] = uniform_knot_vector(p, n);
    for (int i = 0; i < m; ++i) params[d].push_back(i / (m - 1.0));
  }
  Eigen::MatrixXd S(static_cast<long>(m) * m * m, 3);
  long q = 0;
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) S.row(q++) = f(params[0][i], params[1][j], params[2][k]);
  FixedControlPoints fx;
  if (fix_face) {
    Patch shape;
    shape.degrees = deg;
    shape.knots = knots;
    fx.indices = side_control_points(shape, kU0);
    fx.values = Eigen::MatrixXd::Zero(static_cast<long>(fx.indices.size()), 3);
  }
  for (auto _ : st) benchmark::DoNotOptimize(fit_grid(deg, knots, params, S, fx));
  st.counters["samples"] = static_cast<double>(S.rows());
}
BENCHMARK(BM_GridFit40)->ArgNames({"p", "fixed_face"})->Args({2, 0})->Args({3, 0})->Args({3, 1})
    ->Unit(benchmark::kMillisecond);

void BM_ScatteredFit(benchmark::State& st) {
  const int p = 3, n = static_cast<int>(st.range(0));
  std::array<int, 3> deg = {{p, p, p}};
  std::array<std::vector<double>, 3> knots;
  for (int d = 0; d < 3; ++d) knots[d] = uniform_knot_vector(p, n);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> R(0, 1);
  const long N = 8L * n * n * n;
  Eigen::MatrixXd uvw(N, 3), pts(N, 3);
  for (long i = 0; i < N; ++i) {
    uvw.row(i) << R(rng), R(rng), R(rng);
    pts.row(i) = f(uvw(i, 0), uvw(i, 1), uvw(i, 2));
  }
  for (auto _ : st) benchmark::DoNotOptimize(fit_scattered(deg, knots, uvw, pts, 1e-6));
}
BENCHMARK(BM_ScatteredFit)->ArgName("n")->Arg(10)->Arg(16)->Unit(benchmark::kMillisecond);
}  // namespace

BENCHMARK_MAIN();
