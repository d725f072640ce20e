#include "igaprep/param/surface_projector.h"

#include <string>
#include <vector>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include "igaprep/core/error.h"
#include "igaprep/param/decomposition_mesh.h"

namespace igaprep::param {

namespace {
using K = CGAL::Simple_cartesian<double>;
using Triangle = K::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<K, std::vector<Triangle>::const_iterator>;
}  // namespace

struct SurfaceProjector::Tree {
  std::vector<Triangle> triangles;
  CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> tree;
};

SurfaceProjector::SurfaceProjector(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) : tree_(std::make_unique<Tree>()) {
  if (F.rows() == 0 || F.cols() != 3) throw bad_input("surface projector: need at least one triangle");
  auto point = [&](int v) {
    if (v < 0 || v >= V.rows()) throw bad_input("surface projector: triangle vertex " + std::to_string(v) + " out of range");
    return K::Point_3(V(v, 0), V(v, 1), V(v, 2));
  };
  tree_->triangles.reserve(static_cast<std::size_t>(F.rows()));
  for (Eigen::Index f = 0; f < F.rows(); ++f) tree_->triangles.emplace_back(point(F(f, 0)), point(F(f, 1)), point(F(f, 2)));
  tree_->tree.insert(tree_->triangles.begin(), tree_->triangles.end());
  tree_->tree.accelerate_distance_queries();
}

SurfaceProjector::~SurfaceProjector() = default;
SurfaceProjector::SurfaceProjector(SurfaceProjector&&) noexcept = default;
SurfaceProjector& SurfaceProjector::operator=(SurfaceProjector&&) noexcept = default;

Eigen::Vector3d SurfaceProjector::closest(const Eigen::Vector3d& p, int* triangle) const {
  const auto hit = tree_->tree.closest_point_and_primitive(K::Point_3(p.x(), p.y(), p.z()));
  if (triangle) *triangle = static_cast<int>(hit.second - tree_->triangles.cbegin());
  return {hit.first.x(), hit.first.y(), hit.first.z()};
}

Eigen::Vector3d SurfaceProjector::normal(int triangle) const {
  if (triangle < 0 || static_cast<std::size_t>(triangle) >= tree_->triangles.size())
    throw bad_input("surface projector: triangle " + std::to_string(triangle) + " out of range");
  const Triangle& t = tree_->triangles[static_cast<std::size_t>(triangle)];
  const K::Vector_3 n = CGAL::cross_product(t.vertex(1) - t.vertex(0), t.vertex(2) - t.vertex(0));
  const Eigen::Vector3d e(n.x(), n.y(), n.z());
  return e.norm() > 0.0 ? Eigen::Vector3d(e.normalized()) : Eigen::Vector3d::Zero();
}

Eigen::Vector3d SurfaceProjector::slide(const Eigen::Vector3d& from, const Eigen::Vector3d& to) const {
  int tri = -1;
  const Eigen::Vector3d c0 = closest(from, &tri);
  const double offset = (from - c0).dot(normal(tri));
  const Eigen::Vector3d c1 = closest(to, &tri);
  return c1 + offset * normal(tri);
}

std::vector<SurfaceProjector> surface_projectors(const DecompositionMesh& H) {
  std::vector<SurfaceProjector> out;
  for (int k = 0; k < H.num_surfaces; ++k) {  // surface_faces[n] is M
    const std::vector<int>& rows = H.surface_faces[static_cast<std::size_t>(k)];
    Eigen::MatrixXi F(static_cast<Eigen::Index>(rows.size()), 3);
    for (std::size_t r = 0; r < rows.size(); ++r) F.row(static_cast<Eigen::Index>(r)) = H.tets.F.row(rows[r]);
    out.emplace_back(H.tets.V, F);
  }
  return out;
}

}  // namespace igaprep::param
