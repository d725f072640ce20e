// The genus-3 built-in solid: a smooth tube around a planar frame with three
// holes. Its implicit function is contoured by marching tetrahedra on a Kuhn
// grid, then remeshed isotropically with CGAL. (CGAL's Delaunay surface
// mesher was the first choice, but its refinement queue is ordered by memory
// addresses, so its output changed from one call to the next in one process.)
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "igaprep/mesh/marching_tets.h"
#include "igaprep/mesh/remesh_surface.h"
#include "igaprep/models/shapes.h"

namespace igaprep::models {

namespace {

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

// Negative inside the solid.
double frame_function(const std::vector<Segment2>& segments, double radius, double x, double y, double z) {
  double d = distance_to_segment(x, y, z, segments[0]);
  for (std::size_t i = 1; i < segments.size(); ++i) d = smooth_min(d, distance_to_segment(x, y, z, segments[i]), 0.15);
  return d - radius;
}

// Kuhn (Freudenthal) subdivision of a regular grid: 6 tets per cube, all
// positively oriented, conforming across cubes.
void kuhn_grid(const Eigen::Vector3d& lo, const Eigen::Vector3i& cells, double h, Eigen::MatrixXd& V,
               Eigen::MatrixXi& T) {
  const int nx = cells.x() + 1, ny = cells.y() + 1, nz = cells.z() + 1;
  V.resize(static_cast<Eigen::Index>(nx) * ny * nz, 3);
  auto id = [&](int i, int j, int k) { return i + nx * (j + ny * k); };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) V.row(id(i, j, k)) = (lo + h * Eigen::Vector3d(i, j, k)).transpose();
  // The six paths from corner 000 to 111 through the cube's vertices.
  static const int kPaths[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  T.resize(6 * static_cast<Eigen::Index>(cells.prod()), 4);
  Eigen::Index t = 0;
  for (int k = 0; k < cells.z(); ++k)
    for (int j = 0; j < cells.y(); ++j)
      for (int i = 0; i < cells.x(); ++i)
        for (const auto& path : kPaths) {
          std::array<int, 3> c{{i, j, k}};
          std::array<int, 4> tet;
          tet[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            c[static_cast<std::size_t>(path[s])] += 1;
            tet[static_cast<std::size_t>(s) + 1] = id(c[0], c[1], c[2]);
          }
          const Eigen::Vector3d a = V.row(tet[0]), b = V.row(tet[1]), cc = V.row(tet[2]), d = V.row(tet[3]);
          if ((b - a).cross(cc - a).dot(d - a) < 0) std::swap(tet[2], tet[3]);
          T.row(t++) << tet[0], tet[1], tet[2], tet[3];
        }
}

}  // namespace

mesh::TriMesh make_three_hole_frame(double tube_radius, double edge_length) {
  const std::vector<Segment2> segments = frame_segments();
  // A grid at half the target edge length around the frame (with margin).
  const double h = 0.5 * edge_length;
  const Eigen::Vector3d lo(-1.5 - tube_radius - 2 * h, -0.6 - tube_radius - 2 * h, -tube_radius - 2 * h);
  const Eigen::Vector3d hi = -lo;
  const Eigen::Vector3i cells = ((hi - lo) / h).array().ceil().cast<int>();
  Eigen::MatrixXd V;
  Eigen::MatrixXi T;
  kuhn_grid(lo, cells, h, V, T);
  Eigen::VectorXd field(V.rows());
  for (Eigen::Index i = 0; i < V.rows(); ++i) field(i) = frame_function(segments, tube_radius, V(i, 0), V(i, 1), V(i, 2));
  const mesh::IsoSurface iso = mesh::marching_tets(V, T, field, 0.0);

  // Remesh to well-shaped triangles of the target size; Surface_mesh works on
  // indices, so the result depends only on the input.
  return mesh::remesh_isotropic(iso.mesh, {edge_length, 0.0, 5});
}

}  // namespace igaprep::models
