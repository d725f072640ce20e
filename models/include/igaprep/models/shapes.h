#pragma once
// Deterministic closed surfaces for the built-in models and for tests.
#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::models {

// Icosahedron subdivided `levels` times, projected onto the ellipsoid with
// semi-axes (a, b, c) centred at the origin. 20 * 4^levels triangles, outward.
mesh::TriMesh make_ellipsoid(double a, double b, double c, int levels);

// Torus around the z axis: major radius R, tube radius r, n_major x n_minor
// vertices (2 n_major n_minor triangles), outward.
mesh::TriMesh make_torus(double major_radius, double minor_radius, int n_major, int n_minor);

// A genus-3 solid: the smooth tube of radius `tube_radius` around a planar
// frame with three holes in a row (an outer rounded rectangle and two bars),
// contoured by marching tets and remeshed (CGAL) to triangles of about
// `edge_length`.
mesh::TriMesh make_three_hole_frame(double tube_radius, double edge_length);

}  // namespace igaprep::models
