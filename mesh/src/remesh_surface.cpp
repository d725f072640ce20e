#include "igaprep/mesh/remesh_surface.h"

#include <Eigen/Geometry>

#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "igaprep/core/error.h"
#include "igaprep/mesh/to_surface_mesh.h"

namespace igaprep::mesh {
namespace PMP = CGAL::Polygon_mesh_processing;

TriMesh remesh_isotropic(const TriMesh& surface, const RemeshOptions& o) {
  if (!(o.edge_length > 0.0)) throw bad_input("remesh: the target edge length must be positive");
  SurfaceMesh sm = to_surface_mesh(surface, "remesh: the surface");
  if (o.sharp_angle > 0.0) {
    auto feature = sm.add_property_map<SurfaceMesh::Edge_index, bool>("e:feature", false).first;
    PMP::detect_sharp_edges(sm, o.sharp_angle, feature);
    PMP::isotropic_remeshing(faces(sm), o.edge_length, sm,
                             CGAL::parameters::number_of_iterations(o.iterations).edge_is_constrained_map(feature));
  } else {
    PMP::isotropic_remeshing(faces(sm), o.edge_length, sm, CGAL::parameters::number_of_iterations(o.iterations));
  }
  // collect_garbage renumbers (it moves the last elements into the gaps).
  sm.collect_garbage();
  return from_surface_mesh(sm);
}

double triangle_aspect_quantile(const TriMesh& m, double q) {
  std::vector<double> aspect;
  aspect.reserve(static_cast<std::size_t>(m.F.rows()));
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    const double longest = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    const double twice_area = (b - a).cross(c - a).norm();
    aspect.push_back(twice_area > 0.0 ? longest / twice_area : std::numeric_limits<double>::infinity());
  }
  if (aspect.empty()) return 0.0;
  const auto k = static_cast<std::ptrdiff_t>(std::clamp(q, 0.0, 1.0) * static_cast<double>(aspect.size() - 1));
  std::nth_element(aspect.begin(), aspect.begin() + k, aspect.end());
  return aspect[static_cast<std::size_t>(k)];
}

double median_edge_length(const TriMesh& m) {
  std::vector<double> len;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) len.push_back((m.V.row(m.F(f, k)) - m.V.row(m.F(f, (k + 1) % 3))).norm());
  if (len.empty()) return 0.0;
  std::nth_element(len.begin(), len.begin() + static_cast<std::ptrdiff_t>(len.size() / 2), len.end());
  return len[len.size() / 2];
}

}  // namespace igaprep::mesh
