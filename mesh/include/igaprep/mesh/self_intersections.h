#pragma once
// Whether a triangle surface (closed or a sheet with boundary) crosses
// itself, decided with CGAL's exact predicates: triangles that share only a
// vertex or an edge do not count.
#include <optional>
#include <utility>
#include <vector>

#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::mesh {

// Inputs: a triangle surface.
// Output: the pairs of intersecting triangles (indices into F; empty when
// the surface does not cross itself), or nothing when the question cannot be
// decided because CGAL cannot hold the surface (not an oriented 2-manifold,
// or an index out of range; see try_to_surface_mesh).
std::optional<std::vector<std::pair<int, int>>> find_self_intersections(const TriMesh& mesh);

}  // namespace igaprep::mesh
