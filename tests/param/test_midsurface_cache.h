#pragma once
// The midsurface of each built-in model, built once per test process and
// shared by the midsurface, polycube and base-surface tests; plus geometric
// checks written independently of the code under test.
#include <cmath>
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "igaprep/models/builtin_models.h"
#include "igaprep/param/midsurface_pipeline.h"

namespace midsurface_test {

struct Case {
  igaprep::models::BuiltinModel model;
  igaprep::param::MidsurfaceResult result;
  double diag = 0.0;  // bounding-box diagonal of T1
};

// variant: "auto", "plane" or "loops" (sphere2 only for the last two).
inline const Case& cached(const std::string& name, const std::string& variant = "auto") {
  static std::map<std::string, std::unique_ptr<Case>> cache;
  const std::string key = name + "/" + variant;
  auto it = cache.find(key);
  if (it != cache.end()) return *it->second;
  auto c = std::make_unique<Case>();
  c->model = igaprep::models::make_builtin_model(name);
  const auto& T1 = c->model.surfaces[0];
  c->diag = (T1.V.colwise().maxCoeff() - T1.V.colwise().minCoeff()).norm();
  igaprep::param::MidsurfaceOptions o;
  if (variant == "plane") {
    o.cut = igaprep::param::MidsurfaceOptions::CutKind::Plane;
    o.plane.point = Eigen::Vector3d(0.05, -0.02, 0.03);
    o.plane.normal = Eigen::Vector3d(0.1, 0.15, 1.0);
  } else if (variant == "loops") {
    // A T1 that carries a smooth closed edge path (the plane y + 0.3 z = 0.02
    // inserted as edges), and that path given as explicit vertex indices.
    // (Staircase paths along the original triangles can make M0 non-manifold
    // at a loop edge on this coarse tet mesh: see docs/midsurface.md.)
    igaprep::param::CutPlane p;
    p.point = Eigen::Vector3d(0.0, 0.02, 0.0);
    p.normal = Eigen::Vector3d(0.0, 1.0, 0.3);
    const auto plane_cut = igaprep::param::cut_by_plane(T1, p, name);
    c->model.surfaces[0] = plane_cut.surface;
    o.cut = igaprep::param::MidsurfaceOptions::CutKind::Loops;
    o.loops = plane_cut.loops;
  }
  c->result = igaprep::param::build_midsurface(c->model.surfaces, o, name);
  return *cache.emplace(key, std::move(c)).first->second;
}

// Distance from p to triangle abc.
inline double point_triangle_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                      const Eigen::Vector3d& c) {
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double nn = n.squaredNorm();
  if (nn > 0) {
    const Eigen::Vector3d q = p - n * (n.dot(p - a) / nn);
    const double u = n.dot((b - q).cross(c - q)), v = n.dot((c - q).cross(a - q)), w = n.dot((a - q).cross(b - q));
    if (u >= 0 && v >= 0 && w >= 0) return (p - q).norm();
  }
  auto seg = [&](const Eigen::Vector3d& x, const Eigen::Vector3d& y) {
    const double t = std::clamp((p - x).dot(y - x) / std::max((y - x).squaredNorm(), 1e-300), 0.0, 1.0);
    return (p - (x + t * (y - x))).norm();
  };
  return std::min({seg(a, b), seg(b, c), seg(c, a)});
}

inline double distance_to_surface(const Eigen::Vector3d& p, const igaprep::mesh::TriMesh& S) {
  double d = 1e300;
  for (int f = 0; f < S.F.rows(); ++f)
    d = std::min(d, point_triangle_distance(p, S.V.row(S.F(f, 0)), S.V.row(S.F(f, 1)), S.V.row(S.F(f, 2))));
  return d;
}

// Generalized winding number of a closed surface at p (1 inside, 0 outside).
inline double winding_number(const Eigen::Vector3d& p, const igaprep::mesh::TriMesh& S) {
  double w = 0.0;
  for (int f = 0; f < S.F.rows(); ++f) {
    const Eigen::Vector3d a = S.V.row(S.F(f, 0)).transpose() - p, b = S.V.row(S.F(f, 1)).transpose() - p,
                          c = S.V.row(S.F(f, 2)).transpose() - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double num = a.dot(b.cross(c));
    const double den = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    w += 2.0 * std::atan2(num, den);
  }
  return w / (4.0 * M_PI);
}

// The cut variants the midsurface-stage tests run on: every model with its
// automatic cut, and sphere2 with a plane and with explicit loops.
struct Variant {
  std::string model, variant;
  int genus;
};
inline void PrintTo(const Variant& v, std::ostream* os) { *os << v.model << "/" << v.variant; }
inline const std::vector<Variant> kVariants = {
    {"sphere2", "auto", 0}, {"ring2", "auto", 1}, {"torus3", "auto", 3}, {"sphere2", "plane", 0}, {"sphere2", "loops", 0}};
inline std::string variant_name(const ::testing::TestParamInfo<Variant>& info) {
  return info.param.model + "_" + info.param.variant;
}

}  // namespace midsurface_test
