#include "igaprep/mesh/ray_caster.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <vector>

namespace igaprep::mesh {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangles = std::vector<Kernel::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Kernel::Point_3 to_point(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

}  // namespace

struct RayCaster::Impl {
  Triangles triangles;
  Tree tree;
};

RayCaster::RayCaster(const TriMesh& mesh) : impl_(std::make_unique<Impl>()) {
  impl_->triangles.reserve(static_cast<std::size_t>(mesh.F.rows()));
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    impl_->triangles.emplace_back(to_point(a), to_point(b), to_point(c));
  }
  impl_->tree.insert(impl_->triangles.cbegin(), impl_->triangles.cend());
  impl_->tree.build();
}

RayCaster::~RayCaster() = default;

std::optional<RayHit> RayCaster::first_hit(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                           int skip_face) const {
  const auto begin = impl_->triangles.cbegin();
  const auto skip = [&](Triangles::const_iterator id) { return id - begin == skip_face; };
  const Kernel::Ray_3 ray(to_point(origin), Kernel::Vector_3(direction.x(), direction.y(), direction.z()));
  const auto hit = impl_->tree.first_intersection(ray, skip);
  if (!hit) return std::nullopt;
  const auto* p = boost::get<Kernel::Point_3>(&hit->first);
  if (!p) return std::nullopt;  // the ray runs inside a face's plane
  RayHit h;
  h.face = static_cast<int>(hit->second - begin);
  h.point = Eigen::Vector3d(p->x(), p->y(), p->z());
  h.distance = (h.point - origin).norm();
  return h;
}

}  // namespace igaprep::mesh
