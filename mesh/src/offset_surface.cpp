#include "igaprep/mesh/offset_surface.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Random.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/facets_in_complex_3_to_triangle_mesh.h>
#include <CGAL/refine_mesh_3.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <unordered_map>
#include <vector>

#include "cgal_surface.h"
#include "igaprep/core/error.h"

namespace igaprep::mesh {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using detail::Kernel;
using detail::Point3;
using detail::SurfaceMesh;
using Side = CGAL::Side_of_triangle_mesh<SurfaceMesh, Kernel>;
using Tree = Side::AABB_tree;
using Domain = CGAL::Labeled_mesh_domain_3<Kernel>;
using Tr = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;
using Criteria = CGAL::Mesh_criteria_3<Tr>;

std::string fmt(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

double mean_edge_length(const TriMesh& m) {
  double sum = 0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int c = 0; c < 3; ++c) sum += (m.V.row(m.F(f, c)) - m.V.row(m.F(f, (c + 1) % 3))).norm();
  return sum / (3.0 * m.F.rows());
}

// Early-exit AABB traversal: is any input triangle closer than sqrt(r2) to p?
// Much cheaper than a closest-point query, and the offset only needs that.
struct WithinDistance {
  const Tree* tree;
  Point3 p;
  double r2;
  bool found = false;
  bool go_further() const { return !found; }
  void intersection(const Point3&, const Tree::Primitive& primitive) {
    const auto triangle = CGAL::internal::Primitive_helper<Tree::AABB_traits>::get_datum(primitive, tree->traits());
    if (CGAL::squared_distance(p, triangle) < r2) found = true;
  }
  template <class Node>
  bool do_intersect(const Point3&, const Node& node) const {
    const CGAL::Bbox_3& b = node.bbox();
    double d2 = 0;
    const double q[3] = {p.x(), p.y(), p.z()};
    for (int i = 0; i < 3; ++i) {
      const double lo = b.min(i), hi = b.max(i);
      const double e = q[i] < lo ? lo - q[i] : (q[i] > hi ? q[i] - hi : 0.0);
      d2 += e * e;
    }
    return d2 < r2;
  }
};

// Offset indicator: -1 strictly deeper than D inside the surface, +1
// elsewhere. Mesh_3's labelled domain only uses its sign.
struct OffsetFunction {
  const Tree* tree;
  const Side* side;
  double distance;
  double operator()(const Point3& p) const {
    WithinDistance near{tree, p, distance * distance};
    tree->traversal(p, near);
    if (near.found) return 1.0;  // within D of the surface, on either side
    return (*side)(p) == CGAL::ON_BOUNDED_SIDE ? -1.0 : 1.0;
  }
};

// Local thickness: the length of the inward ray to the next hit of the
// surface, under each input vertex and (with_faces) each face centre, which
// sees a coarse mesh's thinnest places, face to face; ascending. Used only
// to say why an offset failed and to suggest a working D.
std::vector<double> thickness_samples(const SurfaceMesh& sm, const Tree& tree, double eps, bool with_faces) {
  std::vector<double> t;
  auto inward_ray_length = [&](const Point3& at, const Kernel::Vector_3& n) {
    const Point3 p = at - eps * n;
    auto hit = tree.first_intersection(Kernel::Ray_3(p, -n));
    if (!hit) return;
    if (const Point3* q3 = boost::get<Point3>(&hit->first)) t.push_back(std::sqrt(CGAL::squared_distance(p, *q3)));
  };
  auto vnormals = sm.property_map<SurfaceMesh::Vertex_index, Kernel::Vector_3>("v:offset_normal").first;
  for (auto v : sm.vertices()) inward_ray_length(sm.point(v), vnormals[v]);
  if (with_faces)
    for (auto f : sm.faces()) {
      const auto h = sm.halfedge(f);
      const Point3 c = CGAL::centroid(sm.point(sm.source(h)), sm.point(sm.target(h)), sm.point(sm.target(sm.next(h))));
      inward_ray_length(c, PMP::compute_face_normal(f, sm));
    }
  std::sort(t.begin(), t.end());
  return t;
}

double percentile(const std::vector<double>& sorted, double q) {
  return sorted.empty() ? 0.0 : sorted[static_cast<std::size_t>(q * static_cast<double>(sorted.size() - 1))];
}

// Seeds of the offset surface: under each input vertex, where f changes
// sign between depth D/2 and 3D/2 along the inward normal, at least
// `spacing` apart (0: all of them); lo: the input's lowest corner.
template <class Normals>
void seed_offset(C3t3& c3t3, const SurfaceMesh& sm, const Normals& vnormals, const Domain& domain,
                 const OffsetFunction& f, double D, double spacing, const Eigen::RowVector3d& lo) {
  std::unordered_map<std::uint64_t, std::vector<Point3>> grid;
  auto cell_of = [&](const Point3& p, int dx, int dy, int dz) {
    const std::uint64_t ix = static_cast<std::uint64_t>(std::floor((p.x() - lo(0)) / spacing) + 2 + dx);
    const std::uint64_t iy = static_cast<std::uint64_t>(std::floor((p.y() - lo(1)) / spacing) + 2 + dy);
    const std::uint64_t iz = static_cast<std::uint64_t>(std::floor((p.z() - lo(2)) / spacing) + 2 + dz);
    return (ix * 1000003ULL + iy) * 1000003ULL + iz;
  };
  auto near_a_seed = [&](const Point3& p) {
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          auto it = grid.find(cell_of(p, dx, dy, dz));
          if (it == grid.end()) continue;
          for (const Point3& q : it->second)
            if (CGAL::squared_distance(p, q) < spacing * spacing) return true;
        }
    return false;
  };
  auto intersect = domain.construct_intersection_object();
  auto cwp = c3t3.triangulation().geom_traits().construct_weighted_point_3_object();
  for (auto v : sm.vertices()) {
    const Kernel::Vector_3 n = vnormals[v];
    const Point3 a = sm.point(v) - 0.5 * D * n, b = sm.point(v) - 1.5 * D * n;
    if (!(f(a) > 0 && f(b) < 0)) continue;
    const auto hit = intersect(Kernel::Segment_3(a, b));
    if (std::get<2>(hit) == 0) continue;
    const Point3 p = std::get<0>(hit);
    if (spacing > 0) {
      if (near_a_seed(p)) continue;
      grid[cell_of(p, 0, 0, 0)].push_back(p);
    }
    auto vh = c3t3.triangulation().insert(cwp(p));
    if (vh != Tr::Vertex_handle()) {
      c3t3.set_dimension(vh, 2);
      c3t3.set_index(vh, std::get<1>(hit));
    }
  }
}

}  // namespace

TriMesh offset_inward(const TriMesh& surface, const OffsetOptions& options) {
  const double D = options.distance;
  if (!(D > 0) || !std::isfinite(D)) throw bad_input("offset_inward: the offset distance must be positive, got " + fmt(D));
  if (surface.F.rows() < 4) throw bad_input("offset_inward: the surface has fewer than 4 triangles");
  SurfaceMesh sm = to_surface_mesh(surface, "offset_inward: input surface");
  if (!CGAL::is_closed(sm)) throw bad_input("offset_inward: the input surface is not closed");
  const detail::SurfaceTopology topo_in = detail::surface_topology(surface);
  const double h = options.edge_length > 0 ? options.edge_length : mean_edge_length(surface);

  const Eigen::RowVector3d lo = surface.V.colwise().minCoeff(), hi = surface.V.colwise().maxCoeff();
  const double diag = (hi - lo).norm();

  // Everything below uses fixed seeds so the same input gives the same output.
  CGAL::get_default_random() = CGAL::Random(0);
  CGAL::Random rng(0);

  Tree tree(faces(sm).first, faces(sm).second, sm);
  tree.build();
  Side side(tree);
  OffsetFunction f{&tree, &side, D};

  const Eigen::RowVector3d center = 0.5 * (lo + hi);
  const Point3 c(center(0), center(1), center(2));
  const double radius = 0.5 * diag * 1.05;
  Domain domain = Domain::create_implicit_mesh_domain(
      f, Kernel::Sphere_3(c, radius * radius),
      CGAL::parameters::relative_error_bound = 1e-6, CGAL::parameters::p_rng = &rng);

  auto vnormals = sm.add_property_map<SurfaceMesh::Vertex_index, Kernel::Vector_3>("v:offset_normal").first;
  PMP::compute_vertex_normals(sm, vnormals);
  // Seeds about 0.7 h apart; a coarse input (an icosahedron) has so few
  // vertices that this leaves fewer than the 4 seeds meshing needs: then
  // every vertex's seed.
  C3t3 c3t3;
  seed_offset(c3t3, sm, vnormals, domain, f, D, 0.7 * h, lo);
  if (c3t3.triangulation().number_of_vertices() < 4) {
    c3t3 = C3t3();
    seed_offset(c3t3, sm, vnormals, domain, f, D, 0.0, lo);
  }

  auto refuse = [&](const std::string& what) {
    const double t5 = percentile(thickness_samples(sm, tree, 1e-9 * diag, false), 0.05);
    const double thinnest = percentile(thickness_samples(sm, tree, 1e-9 * diag, true), 0.0);
    const std::string head = "offset_inward: offsetting by D = " + fmt(D) + " " + what;
    // Nowhere thinner than 2 D: halving D would not help (it did not on a coarse mesh).
    if (thinnest > 2 * D)
      return bad_input(head + ": the solid is nowhere thinner than 2 D = " + fmt(2 * D) + " (" + fmt(thinnest) +
                       " at least), so the cause is the mesh: its mean edge " + fmt(h) +
                       " is too long to carry the offset surface; remesh the surface finer");
    const bool below = 0.5 * t5 < D;  // else the thin places are fewer than 5 %
    return bad_input(head + ": the solid is thinner than 2 D = " + fmt(2 * D) + " somewhere (down to " + fmt(thinnest) +
                     "); try D < " + fmt(below ? 0.5 * t5 : 0.5 * thinnest) +
                     (below ? " (half the 5th percentile of the local thickness)" : " (half the thinnest place)"));
  };

  if (c3t3.triangulation().number_of_vertices() < 4) {
    throw refuse("leaves no surface (the offset vanishes)");
  }

  Criteria criteria(CGAL::parameters::facet_angle = 25.0, CGAL::parameters::facet_size = h,
                    CGAL::parameters::facet_distance = std::min(0.1 * h, 0.25 * D));
  CGAL::refine_mesh_3(c3t3, domain, criteria, CGAL::parameters::no_perturb(), CGAL::parameters::no_exude(),
                     CGAL::parameters::manifold());

  SurfaceMesh out_sm;
  CGAL::facets_in_complex_3_to_triangle_mesh(c3t3, out_sm);
  if (out_sm.number_of_faces() == 0) throw refuse("leaves no surface (the offset vanishes)");
  if (!CGAL::is_closed(out_sm)) {
    throw internal_error("offset_inward: the meshed offset surface (D = " + fmt(D) + ") is not closed");
  }
  TriMesh out = from_surface_mesh(out_sm);
  const detail::SurfaceTopology topo_out = detail::surface_topology(out);
  if (topo_out.genus != topo_in.genus || topo_out.components != topo_in.components) {
    throw refuse("changes the topology (genus " + std::to_string(topo_in.genus) + " -> " +
                 std::to_string(topo_out.genus) + ", " + std::to_string(topo_in.components) + " -> " +
                 std::to_string(topo_out.components) + " components)");
  }
  // Parts of the solid thinner than 2 D vanish without changing the topology
  // (e.g. a thin blade or rim): every input vertex must have the offset within
  // a few D (at a convex edge with dihedral angle a, the nearest offset point is
  // D / sin(a / 2) away; 4 D allows edges down to about 30 degrees).
  {
    using OutTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<SurfaceMesh>>>;
    OutTree out_tree(faces(out_sm).first, faces(out_sm).second, out_sm);
    out_tree.accelerate_distance_queries();
    const double limit = 4.0 * D;
    int far = 0, first_far = -1;
    double farthest = 0;
    for (Eigen::Index i = 0; i < surface.V.rows(); ++i) {
      const double d2 = out_tree.squared_distance(Point3(surface.V(i, 0), surface.V(i, 1), surface.V(i, 2)));
      if (d2 > limit * limit) {
        if (first_far < 0) first_far = static_cast<int>(i);
        ++far;
        farthest = std::max(farthest, std::sqrt(d2));
      }
    }
    if (far > 0) {
      const Eigen::RowVector3d q = surface.V.row(first_far);
      throw refuse("vanishes in places: " + std::to_string(far) + " input vertices (e.g. vertex " +
                   std::to_string(first_far) + " at (" + fmt(q(0)) + ", " + fmt(q(1)) + ", " + fmt(q(2)) +
                   ")) are more than 4 D from the offset surface, up to " + fmt(farthest / D) + " D");
    }
  }
  if (!PMP::is_outward_oriented(out_sm)) {
    PMP::reverse_face_orientations(out_sm);
    out = from_surface_mesh(out_sm);
  }
  if (PMP::does_self_intersect(out_sm)) {
    throw internal_error("offset_inward: the meshed offset surface (D = " + fmt(D) + ") self-intersects");
  }
  return out;
}

}  // namespace igaprep::mesh
