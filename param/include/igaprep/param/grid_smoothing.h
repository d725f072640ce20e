#pragma once
// Smoothing of sampled point grids by least squares onto low-degree
// polynomials, keeping what a neighbouring grid shares: a side keeps its two
// end points, a face keeps its four (already smoothed) sides. The sampled
// maps of the decomposition (M at a grid of its (u, v) domain, the lids at
// w = w0) are piecewise linear with bumps of a few sample spacings; the
// trivariate fit cannot follow them and the thin blocks fold. The smoothed
// maps are polynomials plus a Coons blend of their sides.
#include <array>
#include <vector>

#include <Eigen/Core>

namespace igaprep::param {

// Inputs: points[k] sampled at params[k] (ascending, params.front() = 0,
// params.back() = 1), degree >= 2. Output: the points of the curve
// (1 - t) p0 + t p1 + t (1 - t) q(t), q of degree (degree - 2) fitted by least
// squares, at the same params. The ends are unchanged (bit for bit).
std::vector<Eigen::Vector3d> smooth_polyline(const std::vector<Eigen::Vector3d>& points,
                                             const std::vector<double>& params, int degree);

// Inputs: an m x m grid (first index fastest) sampled at params x params,
// degree >= 2. Output: each side smoothed by smooth_polyline (from its own
// samples only, in increasing index order: two grids that share a side with
// the same samples get the same side), then the inside as the Coons patch of
// the four sides plus s (1 - s) t (1 - t) Q(s, t), Q of degree (degree - 2)
// in each direction fitted by least squares.
//
// kept.corners (grid corners (0, 0), (m - 1, 0), (0, m - 1), (m - 1, m - 1)),
// kept.end_share (0 to 0.5): within end_share of a side's parameters from a
// kept corner the smoothed side blends back to its samples, (1 - d / end_share)^2
// of them at distance d. A layout corner on M's boundary maps a 90 degree
// corner of the (u, v) domain onto a smooth boundary, and the sides bend
// there within a few samples; the polynomial irons the bend out and opens
// the corner towards 180 degrees, where the shells grown from it fold. The
// blend depends on the side's samples and its ends' flags only, so two grids
// that share a side and flag its ends alike still get the same side.
struct KeptCorners {
  std::array<bool, 4> corners{};
  double end_share = 0.0;
};
std::vector<Eigen::Vector3d> smooth_grid(const std::vector<Eigen::Vector3d>& grid, const std::vector<double>& params,
                                         int degree, const KeptCorners& kept = {});

}  // namespace igaprep::param
