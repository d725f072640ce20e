#pragma once
// Test models for the elasticity solver, built exactly in B-spline/NURBS
// form: boxes, annulus sectors (quarter cylinders), reoriented patches,
// interface detection and boundary labelling by geometry.
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "igaprep/spline/find_interfaces.h"
#include "igaprep/spline/spline.h"

namespace solve_test {

using igaprep::spline::MultiPatch;
using igaprep::spline::Patch;

// Uniform breakpoints a..b with `elements` elements.
inline std::vector<double> breaks(int elements, double a = 0.0, double b = 1.0) {
  std::vector<double> x(elements + 1);
  for (int i = 0; i <= elements; ++i) x[i] = a + (b - a) * i / elements;
  return x;
}

// B-spline patch of the box [lo, hi] (the identity map, control points at the
// Greville abscissae), given degrees and elements per direction.
inline Patch box_patch(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, std::array<int, 3> degrees,
                       std::array<int, 3> elements) {
  Patch p;
  p.degrees = degrees;
  std::array<std::vector<double>, 3> g;
  for (int d = 0; d < 3; ++d) {
    p.knots[d] = igaprep::spline::knot_vector_from_breaks(breaks(elements[d]), degrees[d]);
    g[d] = igaprep::spline::greville_abscissae(p.knots[d], degrees[d]);
  }
  p.control_points.resize(p.count(0) * p.count(1) * p.count(2), 3);
  for (int k = 0; k < p.count(2); ++k)
    for (int j = 0; j < p.count(1); ++j)
      for (int i = 0; i < p.count(0); ++i)
        p.control_points.row(p.index(i, j, k)) =
            (lo.array() + (hi - lo).array() * Eigen::Array3d(g[0][i], g[1][j], g[2][k])).matrix().transpose();
  return p;
}

// Exact NURBS of the sector r0 < r < r1, th0 < theta < th1 (|th1 - th0| < pi),
// z0 < z < z1: u radial, v angular (one quadratic rational segment), w along z.
// Degrees (2, 2, 2) after elevating u and w (so refinement stays uniform).
inline Patch sector_patch(double r0, double r1, double th0, double th1, double z0, double z1) {
  Patch p;
  p.degrees = {1, 2, 1};
  p.knots[0] = {0, 0, 1, 1};
  p.knots[1] = {0, 0, 0, 1, 1, 1};
  p.knots[2] = {0, 0, 1, 1};
  p.control_points.resize(12, 3);
  p.weights.resize(12);
  const double half = 0.5 * (th1 - th0), c = std::cos(half);
  const double ang[3] = {th0, th0 + half, th1};
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 2; ++i) {
        const double r = (i == 0 ? r0 : r1) / (j == 1 ? c : 1.0);
        p.control_points.row(p.index(i, j, k)) << r * std::cos(ang[j]), r * std::sin(ang[j]), k == 0 ? z0 : z1;
        p.weights(p.index(i, j, k)) = j == 1 ? c : 1.0;
      }
  p = igaprep::spline::elevate_degree(p, 0, 1);
  p = igaprep::spline::elevate_degree(p, 2, 1);
  return p;
}

// The same geometry with direction k of the result running along direction
// perm[k] of `in`, reversed when flip[k]. Exact (only the numbering changes).
inline Patch reorient(const Patch& in, std::array<int, 3> perm, std::array<bool, 3> flip) {
  Patch out;
  out.material = in.material;
  for (int k = 0; k < 3; ++k) {
    out.degrees[k] = in.degrees[perm[k]];
    std::vector<double> U = in.knots[perm[k]];
    if (flip[k]) {
      const double a = U.front(), b = U.back();
      std::reverse(U.begin(), U.end());
      for (double& x : U) x = a + b - x;
    }
    out.knots[k] = U;
  }
  const int n = in.control_points.rows();
  out.control_points.resize(n, 3);
  if (in.rational()) out.weights.resize(n);
  for (int k = 0; k < out.count(2); ++k)
    for (int j = 0; j < out.count(1); ++j)
      for (int i = 0; i < out.count(0); ++i) {
        const int idx[3] = {i, j, k};
        int src[3];
        for (int d = 0; d < 3; ++d) {
          const int m = out.count(d);
          src[perm[d]] = flip[d] ? m - 1 - idx[d] : idx[d];
        }
        const int a = in.index(src[0], src[1], src[2]), b = out.index(i, j, k);
        out.control_points.row(b) = in.control_points.row(a);
        if (in.rational()) out.weights(b) = in.weights(a);
      }
  return out;
}

// Finds every pair of patch sides with coincident control points and records
// it as an interface (the library's geometric matching).
inline void find_interfaces(MultiPatch& mp, double tol = 1e-9) { igaprep::spline::find_interfaces(mp, tol); }

// Labels every side that is not on an interface by the name `classify`
// returns for the physical point at the side's parameter centre.
inline void label_boundaries(MultiPatch& mp, const std::function<std::string(const Eigen::Vector3d&)>& classify) {
  using namespace igaprep::spline;
  mp.boundaries.clear();
  for (int p = 0; p < static_cast<int>(mp.patches.size()); ++p)
    for (const Side s : Side::all()) {
      bool on_interface = false;
      for (const auto& itf : mp.interfaces)
        on_interface |= (itf.patch_a == p && itf.side_a == s) || (itf.patch_b == p && itf.side_b == s);
      if (on_interface) continue;
      const Patch& pa = mp.patches[p];
      Eigen::Vector3d uvw;
      for (int d = 0; d < 3; ++d) {
        const double lo = pa.knots[d].front(), hi = pa.knots[d].back();
        uvw(d) = 0.5 * (lo + hi);
      }
      const int d = s.direction();
      uvw(d) = s.parameter() ? pa.knots[d].back() : pa.knots[d].front();
      const std::string name = classify(evaluate_point(pa, uvw));
      auto it = std::find(mp.labels.begin(), mp.labels.end(), name);
      int label = static_cast<int>(it - mp.labels.begin());
      if (it == mp.labels.end()) mp.labels.push_back(name);
      mp.boundaries.push_back({p, s, label});
    }
}

// Two unit cubes side by side along x, 2 elements per direction, one
// material (steel-like, E = 1000, nu = 0.3); sides labelled "base" (x = 0),
// "end" (x = 2) and "free".
inline MultiPatch two_box_bar(int degree) {
  MultiPatch mp;
  mp.patches = {box_patch({0, 0, 0}, {1, 1, 1}, {degree, degree, degree}, {2, 2, 2}),
                box_patch({1, 0, 0}, {2, 1, 1}, {degree, degree, degree}, {2, 2, 2})};
  mp.materials = {{"steel", 1000.0, 0.3}};
  find_interfaces(mp);
  label_boundaries(mp, [](const Eigen::Vector3d& x) {
    if (std::abs(x(0)) < 1e-9) return std::string("base");
    if (std::abs(x(0) - 2) < 1e-9) return std::string("end");
    return std::string("free");
  });
  return mp;
}

}  // namespace solve_test
