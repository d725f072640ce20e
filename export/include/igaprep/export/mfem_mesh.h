#pragma once
// MFEM NURBS mesh v1.0 in patch form (mfem/mesh/nurbs.cpp NURBSExtension,
// Mesh::LoadPatchTopo): the patch topology (one hexahedron per patch,
// attribute = material + 1; boundary quadrilaterals, attribute = label + 1;
// explicit edges carrying knot-vector indices shared along parallel edges
// and across patches; vertex count), then per patch its knot vectors and
// homogeneous control points (x*w y*w z*w w, u fastest).
//
// The patches must be conforming across interfaces (same number of control
// points and the same knot vector, up to orientation and parameter range, on
// both sides), since MFEM stores one knot vector per edge class.
#include <ostream>
#include <string>

#include "igaprep/spline/multipatch.h"

namespace igaprep::exporter {

// Inputs: model. Output: the mesh text on `out`. Throws bad_input when the
// patches are not conforming in the sense above (names the patches).
void write_mfem_mesh(const spline::MultiPatch& model, std::ostream& out);
void write_mfem_mesh(const spline::MultiPatch& model, const std::string& path);  // atomic

}  // namespace igaprep::exporter
