#pragma once
// Isotropic remeshing of a closed surface (CGAL), for inputs whose triangles
// are too long and thin for the tet mesh and the fields on it (CAD exports).
#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::mesh {

struct RemeshOptions {
  double edge_length = 0.0;     // target; must be positive
  double sharp_angle = 0.0;     // degrees: edges whose faces turn by more are kept as
                                // feature lines (vertices stay on them); 0 = none
  int iterations = 5;
};

// Output: the remeshed surface (vertices on the input surface; the result
// depends only on the input). Throws bad_input for a non-positive length.
TriMesh remesh_isotropic(const TriMesh& surface, const RemeshOptions& options);

// Shape of the triangles: the q-quantile (0..1) of (longest edge)^2 / (2 area),
// about 1.15 for an equilateral triangle; infinite when a triangle has no area.
double triangle_aspect_quantile(const TriMesh& surface, double q);

// The median edge length.
double median_edge_length(const TriMesh& surface);

}  // namespace igaprep::mesh
