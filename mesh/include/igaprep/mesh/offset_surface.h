#pragma once
// Inward offset of a closed surface: the surface at distance D inside it, e.g.
// the boundary between cortical and trabecular bone.
#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::mesh {

struct OffsetOptions {
  double distance = 0.0;     // D > 0, in model units
  double edge_length = 0.0;  // target triangle size; 0 = the input's mean edge length
};

// Inputs: `surface`, closed, 2-manifold, oriented outward, self-intersection
// free (validated); options as above.
// Output: a closed, 2-manifold, self-intersection-free surface, oriented
// outward, whose vertices lie at distance D inside `surface` (up to 1e-6 of
// the bounding-box diagonal), with triangles of about `edge_length`.
// It is the zero set of (distance to `surface` - D) restricted to the inside,
// meshed by CGAL Mesh_3 (restricted Delaunay, manifold criteria) from seeds
// placed at depth D under the input vertices. Deterministic.
// Throws bad_input when the offset vanishes somewhere (the solid is thinner
// than 2 D there): the offset surface is empty, has another genus or number
// of components than `surface`, or some input vertex is more than 4 D from
// it (a thin part vanished without changing the topology). The message
// suggests a smaller D (half the 5th percentile of the local thickness
// measured by inward rays from the input vertices, or D / 2).
// Uses and resets CGAL's default random generator (seed 0).
TriMesh offset_inward(const TriMesh& surface, const OffsetOptions& options);

}  // namespace igaprep::mesh
