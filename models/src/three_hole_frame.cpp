// The genus-3 built-in solid: a smooth tube around a planar frame with three
// holes, meshed with CGAL's (Delaunay-refinement) surface mesher.
#include <CGAL/Complex_2_in_triangulation_3.h>
#include <CGAL/IO/facets_in_complex_2_to_triangle_mesh.h>
#include <CGAL/Implicit_surface_3.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_default_triangulation_3.h>
#include <CGAL/make_surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "igaprep/models/shapes.h"

namespace igaprep::models {

namespace {

using Tr = CGAL::Surface_mesh_default_triangulation_3;
using C2t3 = CGAL::Complex_2_in_triangulation_3<Tr>;
using GT = Tr::Geom_traits;
using Point3 = GT::Point_3;

struct Segment2 {
  double ax, ay, bx, by;
};

// Frame: a 3.0 x 1.2 rectangle (centred at the origin, in the xy plane) with
// two bars at x = -0.5 and x = +0.5, so its tube has three holes.
std::vector<Segment2> frame_segments() {
  const double w = 1.5, h = 0.6, bar = 0.5;
  return {{-w, -h, w, -h}, {w, -h, w, h},    {w, h, -w, h},       {-w, h, -w, -h},
          {-bar, -h, -bar, h}, {bar, -h, bar, h}};
}

double distance_to_segment(double x, double y, double z, const Segment2& s) {
  const double dx = s.bx - s.ax, dy = s.by - s.ay;
  const double t = std::clamp(((x - s.ax) * dx + (y - s.ay) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  const double px = x - (s.ax + t * dx), py = y - (s.ay + t * dy);
  return std::sqrt(px * px + py * py + z * z);
}

// Polynomial smooth minimum: rounds the concave creases where tubes meet.
double smooth_min(double a, double b, double k) {
  const double h = std::max(k - std::abs(a - b), 0.0) / k;
  return std::min(a, b) - h * h * k * 0.25;
}

struct FrameFunction {
  std::vector<Segment2> segments;
  double radius;
  GT::FT operator()(const Point3& p) const {
    double d = distance_to_segment(p.x(), p.y(), p.z(), segments[0]);
    for (std::size_t i = 1; i < segments.size(); ++i)
      d = smooth_min(d, distance_to_segment(p.x(), p.y(), p.z(), segments[i]), 0.15);
    return d - radius;
  }
};

}  // namespace

mesh::TriMesh make_three_hole_frame(double tube_radius, double edge_length) {
  // The surface mesher draws its initial points from CGAL's default random
  // generator, seeded from the clock: fix it so the model is deterministic.
  CGAL::get_default_random() = CGAL::Random(0);
  Tr triangulation;
  C2t3 complex(triangulation);
  const FrameFunction function{frame_segments(), tube_radius};
  // Bounding sphere centred inside the solid (on the right bar).
  const GT::Sphere_3 bounds(Point3(0.5, 0.0, 0.0), 2.5 * 2.5);
  CGAL::Implicit_surface_3<GT, FrameFunction> surface(function, bounds, 1e-7);
  const CGAL::Surface_mesh_default_criteria_3<Tr> criteria(30.0, edge_length, 0.05 * edge_length);
  CGAL::make_surface_mesh(complex, surface, criteria, CGAL::Manifold_tag());

  CGAL::Surface_mesh<Point3> sm;
  CGAL::facets_in_complex_2_to_triangle_mesh(complex, sm);
  if (!CGAL::Polygon_mesh_processing::is_outward_oriented(sm))
    CGAL::Polygon_mesh_processing::reverse_face_orientations(sm);

  mesh::TriMesh m;
  m.V.resize(static_cast<Eigen::Index>(sm.number_of_vertices()), 3);
  for (auto v : sm.vertices()) {
    const Point3& p = sm.point(v);
    m.V.row(static_cast<Eigen::Index>(v.idx())) << p.x(), p.y(), p.z();
  }
  m.F.resize(static_cast<Eigen::Index>(sm.number_of_faces()), 3);
  for (auto f : sm.faces()) {
    int c = 0;
    for (auto v : CGAL::vertices_around_face(sm.halfedge(f), sm))
      m.F(static_cast<Eigen::Index>(f.idx()), c++) = static_cast<int>(v.idx());
  }
  return m;
}

}  // namespace igaprep::models
