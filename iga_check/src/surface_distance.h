#pragma once
// Private to iga_check/: distances to triangle meshes (CGAL AABB trees) and
// their statistics, shared by the fidelity of a model (fidelity.cpp) and of
// a T-NURCC limit surface (tnurcc_fidelity.cpp).
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

#include "igaprep/iga_check/fidelity.h"

namespace igaprep::iga_check::detail {

using K = CGAL::Simple_cartesian<double>;
using Triangles = std::vector<K::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

inline K::Point_3 pt(const Eigen::Vector3d& x) { return K::Point_3(x[0], x[1], x[2]); }
inline Eigen::Vector3d vec(const K::Point_3& p) { return Eigen::Vector3d(p.x(), p.y(), p.z()); }

// Max (with where), mean and 95th percentile of distances, also relative to `diag`.
inline DistanceStats summarize(std::vector<double> d, const std::vector<Eigen::Vector3d>& where, double diag) {
  DistanceStats s;
  s.samples = static_cast<long>(d.size());
  if (d.empty()) return s;
  size_t arg = 0;
  double sum = 0.0;
  for (size_t i = 0; i < d.size(); ++i) {
    sum += d[i];
    if (d[i] > d[arg]) arg = i;
  }
  s.max = d[arg];
  s.max_location = where[arg];
  s.mean = sum / d.size();
  std::sort(d.begin(), d.end());
  const size_t k = static_cast<size_t>(std::ceil(0.95 * d.size())) - 1;
  s.p95 = d[std::min(k, d.size() - 1)];
  s.max_relative = s.max / diag;
  s.mean_relative = s.mean / diag;
  s.p95_relative = s.p95 / diag;
  return s;
}

// Barycentric weights (of corners 1 and 2) of point q in triangle tri's plane.
inline Eigen::Vector2d barycentric(const K::Triangle_3& tri, const K::Point_3& q) {
  const Eigen::Vector3d a = vec(tri[0]), e0 = vec(tri[1]) - a, e1 = vec(tri[2]) - a, r = vec(q) - a;
  const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1), d20 = r.dot(e0), d21 = r.dot(e1);
  const double den = d00 * d11 - d01 * d01;
  if (!(den > 0.0)) return Eigen::Vector2d::Zero();
  return {(d11 * d20 - d01 * d21) / den, (d00 * d21 - d01 * d20) / den};
}

// The triangles of a mesh, for a tree.
inline Triangles mesh_triangles(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  Triangles out;
  out.reserve(F.rows());
  for (int f = 0; f < F.rows(); ++f)
    out.emplace_back(pt(V.row(F(f, 0)).transpose()), pt(V.row(F(f, 1)).transpose()), pt(V.row(F(f, 2)).transpose()));
  return out;
}

}  // namespace igaprep::iga_check::detail
