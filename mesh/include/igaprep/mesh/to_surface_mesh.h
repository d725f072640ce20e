#pragma once
// A TriMesh as a CGAL::Surface_mesh on an exact-predicates kernel, and back:
// the one conversion behind every CGAL step (surface check, nesting, offset,
// tet meshing, self-intersection, the built-in models' remeshing).
// Surface_mesh works on indices, so vertex i and triangle f of the TriMesh are
// vertex i and face f of the Surface_mesh, and results depend only on the input.
//
// This header brings in CGAL. Include it from .cpp files of mesh/ and of
// modules that link CGAL themselves; param/ and the public headers of the
// modules above mesh/ call functions that hide it (e.g. self_intersections.h).
#include <optional>
#include <string>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include "igaprep/core/error.h"  // to_surface_mesh throws igaprep::Error
#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::mesh {

using CgalKernel = CGAL::Exact_predicates_inexact_constructions_kernel;  // exact predicates
using CgalPoint = CgalKernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<CgalPoint>;

// Inputs: a triangle mesh (unreferenced vertices are kept, isolated).
// Output: the Surface_mesh, or nothing when CGAL cannot hold it: V or F
// without 3 columns, a vertex index out of range, or a triangle that would
// make the surface non-manifold or inconsistently oriented.
std::optional<SurfaceMesh> try_to_surface_mesh(const TriMesh& mesh);

// The same, for meshes that must convert: throws Error(BadInput) that starts
// with `what` and names the first triangle at fault.
SurfaceMesh to_surface_mesh(const TriMesh& mesh, const std::string& what);

// Vertices (compacted, in index order: removed ones are skipped) and
// triangles back to arrays.
TriMesh from_surface_mesh(const SurfaceMesh& mesh);

}  // namespace igaprep::mesh
