#include "repair_common.h"

#include <algorithm>
#include <array>
#include <string>

#include "igaprep/core/error.h"
#include "igaprep/spline/curve_surface.h"
#include "igaprep/spline/knot_vector.h"

namespace igaprep::spline::detail {

std::vector<std::vector<Copy>> control_point_copies(const MultiPatch& mp, const GlobalNumbering& num) {
  std::vector<std::vector<Copy>> copies(static_cast<std::size_t>(num.count));
  for (std::size_t pi = 0; pi < mp.patches.size(); ++pi) {
    const Patch& p = mp.patches[pi];
    for (int c = 0; c < p.count(2); ++c)
      for (int b = 0; b < p.count(1); ++b)
        for (int a = 0; a < p.count(0); ++a) {
          const int l = p.index(a, b, c);
          copies[static_cast<std::size_t>(num.global[pi][static_cast<std::size_t>(l)])].push_back({static_cast<int>(pi), l, a, b, c});
        }
  }
  return copies;
}

std::vector<int> control_point_constraints(const MultiPatch& mp, const GlobalNumbering& num,
                                           const std::vector<std::pair<int, Side>>& fixed_sides, bool can_slide) {
  std::vector<int> cons(static_cast<std::size_t>(num.count), kFree);
  auto mark = [&](int patch, Side side, int surface) {
    if (patch < 0 || static_cast<std::size_t>(patch) >= mp.patches.size() || !side.valid())
      throw bad_input("optimize_jacobians: bad side (patch " + std::to_string(patch) + ", side " + std::to_string(side) + ")");
    for (int l : side_control_points(mp.patches[static_cast<std::size_t>(patch)], side)) {
      int& c = cons[static_cast<std::size_t>(num.global[static_cast<std::size_t>(patch)][static_cast<std::size_t>(l)])];
      if (surface == kFixed) c = kFixed;
      else if (c == kFree) c = surface;
      else if (c != surface) c = kFixed;
    }
  };
  for (const BoundarySide& b : mp.boundaries) mark(b.patch, b.side, b.label);
  for (const Interface& itf : mp.interfaces)
    if (itf.surface >= 0) mark(itf.patch_a, itf.side_a, itf.surface), mark(itf.patch_b, itf.side_b, itf.surface);
  for (const auto& [patch, side] : fixed_sides) mark(patch, side, kFixed);
  if (!can_slide)
    for (int& c : cons)
      if (c >= 0) c = kFixed;
  return cons;
}

std::vector<double> repair_sample_params(const std::vector<double>& knots, int points) {
  const std::vector<double> brk = unique_knots(knots);
  std::vector<double> params;
  for (std::size_t e = 0; e + 1 < brk.size(); ++e)
    for (int t = e == 0 ? 0 : 1; t < points; ++t) params.push_back(brk[e] + (brk[e + 1] - brk[e]) * t / (points - 1));
  return params;
}

SampleGrid repair_sample_grid(const Patch& p, int points, const std::vector<Eigen::Vector3d>& extra) {
  SampleGrid params;
  for (std::size_t d = 0; d < 3; ++d) {
    std::vector<double>& t = params[d];
    t = repair_sample_params(p.knots[d], points);
    const double lo = t.front(), hi = t.back();
    for (const Eigen::Vector3d& x : extra)
      if (x[static_cast<Eigen::Index>(d)] > lo && x[static_cast<Eigen::Index>(d)] < hi) t.push_back(x[static_cast<Eigen::Index>(d)]);
    std::sort(t.begin(), t.end());
    t.erase(std::unique(t.begin(), t.end()), t.end());
  }
  return params;
}

double nearest_neighbour(const MultiPatch& mp, const std::vector<Copy>& copies, const Eigen::Vector3d& x) {
  double edge = std::numeric_limits<double>::infinity();
  for (const Copy& c : copies) {
    const Patch& p = mp.patches[static_cast<std::size_t>(c.patch)];
    for (int d = 0; d < 3; ++d)
      for (int step : {-1, 1}) {
        std::array<int, 3> q{{c.a, c.b, c.c}};
        q[static_cast<std::size_t>(d)] += step;
        if (q[static_cast<std::size_t>(d)] < 0 || q[static_cast<std::size_t>(d)] >= p.count(d)) continue;
        const double l = (p.control_points.row(p.index(q[0], q[1], q[2])).transpose() - x).norm();
        if (l > 0.0) edge = std::min(edge, l);
      }
  }
  return edge;
}

}  // namespace igaprep::spline::detail
