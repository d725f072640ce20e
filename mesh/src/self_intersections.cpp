#include "igaprep/mesh/self_intersections.h"

#include <iterator>

#include <CGAL/Polygon_mesh_processing/self_intersections.h>

#include "igaprep/mesh/to_surface_mesh.h"

namespace igaprep::mesh {

std::optional<std::vector<std::pair<int, int>>> find_self_intersections(const TriMesh& mesh) {
  const std::optional<SurfaceMesh> sm = try_to_surface_mesh(mesh);
  if (!sm) return std::nullopt;
  std::vector<std::pair<SurfaceMesh::Face_index, SurfaceMesh::Face_index>> faces;
  CGAL::Polygon_mesh_processing::self_intersections(*sm, std::back_inserter(faces));
  std::vector<std::pair<int, int>> pairs;
  pairs.reserve(faces.size());
  // Face indices are the TriMesh's triangle indices (to_surface_mesh.h).
  for (const auto& [f, g] : faces) pairs.emplace_back(static_cast<int>(f.idx()), static_cast<int>(g.idx()));
  return pairs;
}

}  // namespace igaprep::mesh
