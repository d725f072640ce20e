#pragma once
// Models the solver benchmarks share: a cantilever box [0,4] x [0,1] x [0,1]
// as one B-spline patch of degree p with n elements per direction, its
// u0 side labelled "clamp" and its u1 side "tip".
#include <array>
#include <vector>

#include "igaprep/spline/knot_vector.h"
#include "igaprep/spline/multipatch.h"

inline igaprep::spline::MultiPatch cantilever_box(int p, int n) {
  using namespace igaprep;
  spline::Patch pa;
  pa.degrees = {p, p, p};
  const double size[3] = {4.0, 1.0, 1.0};
  std::vector<double> br(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) br[static_cast<std::size_t>(i)] = double(i) / n;
  std::array<std::vector<double>, 3> g;
  for (std::size_t d = 0; d < 3; ++d) {
    pa.knots[d] = spline::knot_vector_from_breaks(br, p);
    g[d] = spline::greville_abscissae(pa.knots[d], p);
  }
  pa.control_points.resize(pa.count(0) * pa.count(1) * pa.count(2), 3);
  for (int k = 0; k < pa.count(2); ++k)
    for (int j = 0; j < pa.count(1); ++j)
      for (int i = 0; i < pa.count(0); ++i)
        pa.control_points.row(pa.index(i, j, k)) << size[0] * g[0][static_cast<std::size_t>(i)], size[1] * g[1][static_cast<std::size_t>(j)],
            size[2] * g[2][static_cast<std::size_t>(k)];
  spline::MultiPatch mp;
  mp.patches = {pa};
  mp.materials = {{"steel", 210e9, 0.3}};
  mp.labels = {"clamp", "tip"};
  mp.boundaries = {{0, 1, 0}, {0, 2, 1}};
  return mp;
}
