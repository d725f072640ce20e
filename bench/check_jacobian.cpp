// Certification time per Bezier element (p = 2, 3; polynomial and rational)
// and the time to check a 100-patch model (certificate + quality + topology,
// no input surfaces). Figures: docs/performance.md, "analysis-suitability checks".
#include <benchmark/benchmark.h>

#include <cmath>

#include "igaprep/iga_check/bernstein3.h"
#include "igaprep/iga_check/jacobian_certificate.h"
#include "igaprep/iga_check/report.h"
#include "igaprep/spline/bezier_extraction.h"
#include "igaprep/spline/refine.h"

using namespace igaprep;

namespace {

// A gently twisted, bent cube as one Bezier element of degree p (exact for p >= 2).
spline::Patch twisted_patch(int p, const Eigen::Vector3d& shift) {
  spline::Patch P;
  P.degrees = {{p, p, p}};
  for (int d = 0; d < 3; ++d) {
    P.knots[d].assign(p + 1, 0.0);
    P.knots[d].insert(P.knots[d].end(), p + 1, 1.0);
  }
  const int n = (p + 1) * (p + 1) * (p + 1);
  std::array<std::vector<double>, 3> vals;
  for (auto& v : vals) v.resize(n);
  for (int k = 0; k <= p; ++k)
    for (int j = 0; j <= p; ++j)
      for (int i = 0; i <= p; ++i) {
        const double u = double(i) / p, v = double(j) / p, w = double(k) / p;
        const Eigen::Vector3d x(u - 0.3 * w * (v - 0.5) + 0.05 * v * v, v + 0.3 * w * (u - 0.5),
                                w + 0.1 * u * (1 - u) * v);
        const int at = i + (p + 1) * (j + (p + 1) * k);
        for (int c = 0; c < 3; ++c) vals[c][at] = x[c] + shift[c];
      }
  P.control_points.resize(n, 3);
  for (int c = 0; c < 3; ++c) {
    const auto b = iga_check::bernstein_from_samples(P.degrees, vals[c]);
    for (int i = 0; i < n; ++i) P.control_points(i, c) = b.coeffs[i];
  }
  return P;
}

void BM_CertifyElement(benchmark::State& state) {
  const int p = static_cast<int>(state.range(0));
  const bool rational = state.range(1) != 0;
  spline::Patch P = twisted_patch(p, Eigen::Vector3d::Zero());
  if (rational) {
    P.weights = Eigen::VectorXd::Ones(P.control_points.rows());
    for (int i = 0; i < P.weights.size(); ++i) P.weights[i] = 1.0 + 0.2 * std::sin(1.7 * i);
  }
  const spline::PatchExtraction ex = spline::bezier_extraction(P);
  const spline::BezierElement e = spline::bernstein_control_points(P, ex, 0, 0, 0);
  int boxes = 0;
  for (auto _ : state) {
    const auto c = iga_check::certify_element(e, P.degrees);
    boxes = c.boxes;
    benchmark::DoNotOptimize(c.lower_bound);
  }
  state.counters["boxes"] = boxes;
  state.SetLabel(std::string(rational ? "rational" : "polynomial") + " p=" + std::to_string(p));
}
BENCHMARK(BM_CertifyElement)->Args({2, 0})->Args({3, 0})->Args({2, 1})->Args({3, 1})->Unit(benchmark::kMicrosecond);

// 100 patches (10 x 10 side by side), p = 3, 3 x 3 x 3 elements each: 2700 elements.
spline::MultiPatch hundred_patches() {
  spline::MultiPatch mp;
  for (int a = 0; a < 10; ++a)
    for (int b = 0; b < 10; ++b) {
      mp.patches.push_back(spline::refine_uniformly(twisted_patch(3, Eigen::Vector3d(1.5 * a, 1.5 * b, 0)), 2));
      for (const spline::Side s : spline::Side::all()) mp.boundaries.push_back({a * 10 + b, s, 0});
    }
  mp.labels = {"outer"};
  mp.materials.push_back({"m", 1.0, 0.3});
  return mp;
}

void BM_Certify100Patches(benchmark::State& state) {
  const spline::MultiPatch mp = hundred_patches();
  for (auto _ : state) benchmark::DoNotOptimize(iga_check::certify_model(mp).size());
  state.counters["elements"] = 2700;
}
BENCHMARK(BM_Certify100Patches)->Unit(benchmark::kMillisecond);

void BM_Check100Patches(benchmark::State& state) {
  const spline::MultiPatch mp = hundred_patches();
  for (auto _ : state) {
    const auto r = iga_check::build_check_report(mp, {}, {}, {}, "hundred");
    benchmark::DoNotOptimize(r.passed);
  }
  state.counters["elements"] = 2700;
}
BENCHMARK(BM_Check100Patches)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
