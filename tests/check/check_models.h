#pragma once
// Small exact models for the check tests: single Bezier patches from
// polynomial maps, a NURBS quarter annulus, an exact NURBS sphere shell
// (4 patches of revolution) and an icosphere triangle mesh.
#include <Eigen/Core>
#include <cmath>
#include <functional>
#include <map>
#include <algorithm>

#include "igaprep/iga_check/bernstein3.h"
#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/spline/multipatch.h"
#include "igaprep/spline/refine.h"
#include "igaprep/models/shapes.h"

namespace check_test {

using Map = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;

// One Bezier element on [0,1]^3 representing the polynomial map f exactly
// (f must have at most the given degrees; its Bernstein coefficients come from
// interpolation at the uniform grid).
inline igaprep::spline::Patch bezier_patch(const Map& f, const std::array<int, 3>& deg) {
  igaprep::spline::Patch p;
  p.degrees = deg;
  for (int d = 0; d < 3; ++d) {
    p.knots[d].assign(deg[d] + 1, 0.0);
    p.knots[d].insert(p.knots[d].end(), deg[d] + 1, 1.0);
  }
  const int n = (deg[0] + 1) * (deg[1] + 1) * (deg[2] + 1);
  std::array<std::vector<double>, 3> vals;
  for (auto& v : vals) v.resize(n);
  for (int k = 0; k <= deg[2]; ++k)
    for (int j = 0; j <= deg[1]; ++j)
      for (int i = 0; i <= deg[0]; ++i) {
        const Eigen::Vector3d t(double(i) / deg[0], double(j) / deg[1], double(k) / deg[2]);
        const Eigen::Vector3d x = f(t);
        const int at = i + (deg[0] + 1) * (j + (deg[1] + 1) * k);
        for (int c = 0; c < 3; ++c) vals[c][at] = x[c];
      }
  p.control_points.resize(n, 3);
  for (int c = 0; c < 3; ++c) {
    const igaprep::iga_check::Bernstein3 b = igaprep::iga_check::bernstein_from_samples(deg, vals[c]);
    for (int i = 0; i < n; ++i) p.control_points(i, c) = b.coeffs[i];
  }
  return p;
}

inline igaprep::spline::MultiPatch single(const igaprep::spline::Patch& p) {
  igaprep::spline::MultiPatch mp;
  mp.patches.push_back(p);
  mp.labels = {"outer"};
  mp.materials.push_back({"steel", 200e9, 0.3});
  for (const igaprep::spline::Side s : igaprep::spline::Side::all()) mp.boundaries.push_back({0, s, 0});
  return mp;
}

// A gently twisted, bent unit cube: degrees (2,2,1) map represented with degree 3.
inline Eigen::Vector3d twisted(const Eigen::Vector3d& t) {
  const double u = t[0], v = t[1], w = t[2];
  return {u - 0.3 * w * (v - 0.5) + 0.05 * v * v, v + 0.3 * w * (u - 0.5), w + 0.1 * u * (1 - u) * v};
}

// Quarter annulus: radius 2..1 (v), angle 0..90 degrees (u, rational
// quadratic), height 0..1 (w).
inline igaprep::spline::Patch quarter_annulus() {
  igaprep::spline::Patch p;
  p.degrees = {{2, 1, 1}};
  p.knots[0] = {0, 0, 0, 1, 1, 1};
  p.knots[1] = {0, 0, 1, 1};
  p.knots[2] = {0, 0, 1, 1};
  const double s = std::sqrt(0.5);
  const double cx[3] = {1, 1, 0}, cy[3] = {0, 1, 1}, cw[3] = {1, s, 1};
  p.control_points.resize(12, 3);
  p.weights.resize(12);
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) {
        const int at = p.index(i, j, k);
        const double r = 2.0 - j;  // radius decreasing in v: right-handed
        p.control_points.row(at) << r * cx[i], r * cy[i], double(k);
        p.weights[at] = cw[i];
      }
  return p;
}

// Exact sphere shell between radii r0 < r1: 4 patches of revolution
// (u: quarter circle of longitude, v: meridian from south to north pole,
// w: radius). Sides v0/v1 collapse onto the poles.
inline igaprep::spline::MultiPatch sphere_shell(double r0, double r1) {
  using namespace igaprep::spline;
  MultiPatch mp;
  const double s = std::sqrt(0.5);
  const double rho[5] = {0, 1, 1, 1, 0}, z[5] = {-1, -1, 0, 1, 1}, wv[5] = {1, s, 1, s, 1};
  for (int q = 0; q < 4; ++q) {
    const double a = q * M_PI / 2, ca = std::cos(a), sa = std::sin(a);
    const double cx[3] = {ca, ca - sa, -sa}, cy[3] = {sa, sa + ca, ca}, wu[3] = {1, s, 1};
    Patch p;
    p.degrees = {{2, 2, 1}};
    p.knots[0] = {0, 0, 0, 1, 1, 1};
    p.knots[1] = {0, 0, 0, 0.5, 0.5, 1, 1, 1};
    p.knots[2] = {0, 0, 1, 1};
    p.control_points.resize(30, 3);
    p.weights.resize(30);
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 3; ++i) {
          const int at = p.index(i, j, k);
          const double r = k == 0 ? r0 : r1;
          p.control_points.row(at) << r * rho[j] * cx[i], r * rho[j] * cy[i], r * z[j];
          p.weights[at] = wu[i] * wv[j];
        }
    mp.patches.push_back(p);
    Interface itf;
    itf.patch_a = q;
    itf.side_a = kU1;
    itf.patch_b = (q + 1) % 4;
    itf.side_b = kU0;
    mp.interfaces.push_back(itf);
    mp.boundaries.push_back({q, kW0, 1});
    mp.boundaries.push_back({q, kW1, 0});
  }
  mp.labels = {"outer", "inner"};
  mp.materials.push_back({"shell", 1.0, 0.3});
  return mp;
}

// Icosphere of radius r: the icosahedron subdivided `level` times, vertices on
// the sphere, faces outward.
inline igaprep::mesh::TriMesh icosphere(double r, int level) { return igaprep::models::make_ellipsoid(r, r, r, level); }

// The mesh with the vertex nearest `direction` pushed out by `height`.
inline igaprep::mesh::TriMesh with_bump(igaprep::mesh::TriMesh m, const Eigen::Vector3d& direction, double height) {
  int best = 0;
  for (int v = 0; v < m.V.rows(); ++v)
    if (m.V.row(v).dot(direction) > m.V.row(best).dot(direction)) best = v;
  m.V.row(best) *= 1.0 + height / m.V.row(best).norm();
  return m;
}

}  // namespace check_test
