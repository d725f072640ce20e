#include "igaprep/mesh/nesting.h"

#include <cstdio>
#include <optional>

#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/boost/graph/helpers.h>

#include "igaprep/core/error.h"
#include "igaprep/mesh/to_surface_mesh.h"

namespace igaprep::mesh {

namespace {

using Kernel = CgalKernel;
using Point = CgalPoint;
using Triangle = Kernel::Triangle_3;
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, int>;

std::string coords(const Eigen::Vector3d& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%g, %g, %g)", p.x(), p.y(), p.z());
  return buf;
}

Triangle triangle(const TriMesh& m, int f) {
  auto p = [&](int k) { return Point(m.V(m.F(f, k), 0), m.V(m.F(f, k), 1), m.V(m.F(f, k), 2)); };
  return Triangle(p(0), p(1), p(2));
}

std::vector<Box> face_boxes(const TriMesh& m) {
  std::vector<Box> boxes;
  boxes.reserve(m.F.rows());
  for (int f = 0; f < m.F.rows(); ++f) boxes.emplace_back(triangle(m, f).bbox(), f);
  return boxes;
}

// Pairs of faces (one of a, one of b) that share at least a point, decided
// with exact predicates; touching counts.
struct Contact {
  long pairs = 0;
  int face_a = -1, face_b = -1;
};
Contact contacts(const TriMesh& a, const TriMesh& b) {
  std::vector<Box> boxes_a = face_boxes(a), boxes_b = face_boxes(b);
  Contact c;
  CGAL::box_intersection_d(boxes_a.begin(), boxes_a.end(), boxes_b.begin(), boxes_b.end(),
                           [&](const Box& x, const Box& y) {
                             if (!CGAL::do_intersect(triangle(a, x.info()), triangle(b, y.info()))) return;
                             if (c.pairs++ == 0 || std::make_pair(x.info(), y.info()) < std::make_pair(c.face_a, c.face_b)) {
                               c.face_a = x.info();  // the smallest pair, so the message does not depend on the order of the search
                               c.face_b = y.info();
                             }
                           });
  return c;
}

}  // namespace

NestingReport check_nesting(const std::vector<TriMesh>& surfaces, const std::vector<std::string>& names) {
  if (surfaces.size() != names.size())
    throw bad_input("check_nesting: " + std::to_string(surfaces.size()) + " surfaces but " +
                    std::to_string(names.size()) + " names");
  NestingReport report;
  const size_t n = surfaces.size();
  auto quoted = [&](size_t i) { return "'" + names[i] + "'"; };

  // CGAL copies for the inside/outside tests; a surface CGAL cannot hold as a
  // closed mesh cannot be tested.
  std::vector<std::optional<SurfaceMesh>> sm(n);
  std::vector<bool> usable(n, false);
  for (size_t i = 0; i < n; ++i) {
    if (surfaces[i].F.rows() > 0) sm[i] = try_to_surface_mesh(surfaces[i]);
    usable[i] = sm[i] && CGAL::is_closed(*sm[i]);
    if (!usable[i])
      report.errors.push_back(quoted(i) + " is not a closed, manifold, consistently oriented triangle surface, so "
                              "its nesting cannot be decided (run the surface check first)");
  }

  // No two surfaces may cross or touch.
  std::vector<std::vector<bool>> apart(n, std::vector<bool>(n, false));
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j) {
      if (!usable[i] || !usable[j]) continue;
      const Contact c = contacts(surfaces[i], surfaces[j]);
      apart[i][j] = c.pairs == 0;
      if (c.pairs) {
        const TriMesh& a = surfaces[i];
        const Eigen::Vector3d where =
            (a.V.row(a.F(c.face_a, 0)) + a.V.row(a.F(c.face_a, 1)) + a.V.row(a.F(c.face_a, 2))).transpose() / 3.0;
        report.errors.push_back("surfaces " + quoted(i) + " and " + quoted(j) + " intersect or touch: " +
                                std::to_string(c.pairs) + " pairs of faces meet, e.g. face " +
                                std::to_string(c.face_a) + " of " + quoted(i) + " and face " +
                                std::to_string(c.face_b) + " of " + quoted(j) + " near " + coords(where));
      }
    }

  // Each T(i+1) strictly inside T(i). Surfaces that do not meet are either
  // nested or apart, so one vertex decides.
  auto side = [&](size_t outer, size_t inner) {
    CGAL::Side_of_triangle_mesh<SurfaceMesh, Kernel> inside(*sm[outer]);
    const TriMesh& m = surfaces[inner];
    return inside(Point(m.V(m.F(0, 0), 0), m.V(m.F(0, 0), 1), m.V(m.F(0, 0), 2)));
  };
  for (size_t i = 0; i + 1 < n; ++i) {
    if (!apart[i][i + 1]) continue;
    if (side(i, i + 1) == CGAL::ON_BOUNDED_SIDE) continue;
    std::string why = quoted(i + 1) + " is not inside " + quoted(i) + " (surfaces must be listed outermost first, "
                      "each strictly inside the one before)";
    if (side(i + 1, i) == CGAL::ON_BOUNDED_SIDE)
      why += ": " + quoted(i) + " is inside " + quoted(i + 1) + ", so the order is reversed";
    else
      why += ": they lie outside each other";
    report.errors.push_back(why);
  }
  report.nested = report.errors.empty();
  return report;
}

}  // namespace igaprep::mesh
