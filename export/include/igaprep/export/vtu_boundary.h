#pragma once
// The model's labelled boundary as a VTU of Bezier quadrilaterals
// (VTK_BEZIER_QUADRILATERAL = 77), one per element face on a labelled side,
// so that ParaView shows the surfaces (T1, and the outer faces of each
// material) without the interior. The points of a face are its element's
// Bernstein points on that face (exact: the restriction of the element),
// in the order of vtkHigherOrderQuadrilateral::PointIndexFromIJK.
//
// Data arrays: point data "RationalWeights"; cell data "HigherOrderDegrees"
// (3 components, the third 0), "label" (index into the model's labels),
// "patch" and "side" (1..6, G+Smo order); "label" as point data too.
#include <array>
#include <ostream>
#include <string>

#include "igaprep/export/vtu_bezier.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::exporter {

// Inputs: model (every degree >= 1). Output: the VTU text on `out`.
void write_vtu_boundary(const spline::MultiPatch& model, std::ostream& out, const VtuOptions& options = {});

// VTK's point index of Bernstein node (i, j) of a quadrilateral of the given
// degrees (vtkHigherOrderQuadrilateral::PointIndexFromIJK, VTK 9 numbering).
int vtk_quad_point_index(int i, int j, const std::array<int, 2>& degrees);

}  // namespace igaprep::exporter
