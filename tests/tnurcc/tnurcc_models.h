#pragma once
// Small models whose T-NURCC cages are known: a box as one trivariate patch
// and two boxes side by side, degree 3, uniform knots.
#include <gtest/gtest.h>

#include "igaprep/core/error.h"
#include "igaprep/spline/find_interfaces.h"
#include "igaprep/spline/knot_vector.h"
#include "igaprep/spline/multipatch.h"

namespace tnurcc_test {

using namespace igaprep::spline;

// A patch filling [lo, hi], control points on the Greville grid (so the map is affine).
inline Patch box_patch(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, int elements) {
  Patch p;
  p.degrees = {{3, 3, 3}};
  for (int d = 0; d < 3; ++d) p.knots[d] = uniform_knot_vector(3, elements + 3);
  const int n = elements + 3;
  const std::vector<double> g = greville_abscissae(p.knots[0], 3);
  p.control_points.resize(n * n * n, 3);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        p.control_points.row(p.index(i, j, k)) =
            (lo.array() + (hi - lo).array() * Eigen::Array3d(g[i], g[j], g[k])).matrix().transpose();
  return p;
}

// Boxes [x, x + 1] x [0, 1] x [0, 1] for x = 0 .. count - 1, every outer side on label 0.
inline MultiPatch boxes(int count, int elements) {
  MultiPatch mp;
  mp.labels = {"outer"};
  mp.materials = {Material{"m", 1.0, 0.3}};
  for (int b = 0; b < count; ++b) mp.patches.push_back(box_patch({double(b), 0, 0}, {b + 1.0, 1, 1}, elements));
  find_interfaces(mp, 1e-9);
  std::vector<bool> shared(6 * count, false);
  for (const auto& itf : mp.interfaces) {
    shared[6 * itf.patch_a + itf.side_a.array_index()] = true;
    shared[6 * itf.patch_b + itf.side_b.array_index()] = true;
  }
  for (int b = 0; b < count; ++b)
    for (Side s : Side::all())
      if (!shared[6 * b + s.array_index()]) mp.boundaries.push_back({b, s, 0});
  return mp;
}

}  // namespace tnurcc_test
