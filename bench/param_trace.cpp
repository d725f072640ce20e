// Gradient tracing speed: traces per second and tet crossings per second on
// the spherical shell 1 < r < 2 (icosphere level 5 x 8 prism layers = 491,520
// tets), from random points to the marked inner sphere.
// Usage: bench_param_trace [number of traces, default 20000]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <random>

#include "../tests/param/param_meshes.h"
#include "igaprep/param/harmonic_field.h"
#include "igaprep/param/tet_topology.h"
#include "igaprep/param/trace_gradient.h"

using namespace igaprep::param;
using Clock = std::chrono::steady_clock;

static double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 20000;
  const auto s = param_test::spherical_shell(5, 8);
  const auto& m = s.mesh;
  const Eigen::VectorXd u = harmonic_field(m.V, m.T, {{s.inner, 1.0}, {s.outer, 0.0}});
  auto t0 = Clock::now();
  const TetTopology topo = build_tet_topology(m.T, m.V.rows());
  std::printf("mesh: %ld tets; topology built in %.3f s\n", (long)m.T.rows(), since(t0));
  TraceTarget target;
  target.marked = mark_facets(m.T, topo, s.inner_faces);
  const GradientTracer tracer(m.V, m.T, topo, u);
  // Start points: random tets (uniform over tets), random barycentric coordinates.
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> cell(0, int(m.T.rows()) - 1);
  std::exponential_distribution<double> E(1.0);
  std::vector<std::pair<int, Eigen::Vector4d>> starts;
  for (int i = 0; i < n; ++i) {
    Eigen::Vector4d b(E(rng), E(rng), E(rng), E(rng));
    starts.emplace_back(cell(rng), b / b.sum());
  }
  long crossings = 0, points = 0;
  int reached = 0;
  t0 = Clock::now();
  const std::clock_t cpu0 = std::clock();
  for (const auto& [c, b] : starts) {
    const TraceResult t = tracer.trace(c, b, target);
    crossings += t.steps;
    points += t.path.rows();
    reached += t.status == TraceStatus::Reached;
  }
  const double dt = since(t0), cpu = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
  std::printf("CPU time %.3f s: %.2f M crossings/s per CPU second (wall figures below depend on machine load)\n", cpu,
              crossings / cpu * 1e-6);
  std::printf("path points per trace %.1f\n", double(points) / n);
  std::printf("%d traces (%d reached) in %.3f s: %.0f traces/s, %ld tet crossings, %.2f M crossings/s, %.1f "
              "crossings per trace\n",
              n, reached, dt, n / dt, crossings, crossings / dt * 1e-6, double(crossings) / n);
  return 0;
}
