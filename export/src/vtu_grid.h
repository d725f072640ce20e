#pragma once
// Private to export/: the arrays of a VTU of Bezier hexahedra before they are
// written (vtu_bezier.cpp for patches, vtu_extraction.cpp for extraction
// models), and the merging of coincident points.
#include <array>
#include <cstdint>
#include <vector>

#include <ostream>

#include "igaprep/export/vtu_bezier.h"
#include "igaprep/spline/bezier_extraction.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::exporter::detail {

struct Grid {
  std::vector<double> points;   // 3 per point
  std::vector<double> weights;  // 1 per point
  std::vector<double> displacement, von_mises;
  std::vector<int64_t> connectivity, offsets;
  std::vector<int32_t> degrees, material, patch, element;  // degrees, element (i, j, k): 3 per cell
  std::vector<double> min_scaled_jacobian;                // per cell
  std::vector<int32_t> point_material, point_patch;       // per point: slices keep them exact (a point shared by patches: the first)
};

// Points of different cells that coincide (to 1e-10 of the diagonal) with
// the same weight and material become one point, so VTK sees which faces
// are shared (Extract Surface gives the boundary and the material
// interfaces, not every element face). Not for results: von Mises is
// discontinuous between elements, so each cell keeps its own points then.
void share_coincident_points(Grid& g);

// Local Bernstein index (u fastest) -> VTK point index of a Bezier hexahedron.
std::vector<int> vtk_hex_order(const std::array<int, 3>& degrees);

// Appends one Bezier hexahedron: its Bernstein points (weights 1 when it
// has none) in VTK's order (vtk_hex_order of its degrees), its cell data
// and its points' material and patch. Returns the index of its first point.
int64_t add_cell(Grid& g, const spline::BezierElement& be, const std::vector<int>& vtk_of_local,
                 const std::array<int, 3>& degrees, int material, int patch, const std::array<int, 3>& index,
                 double min_scaled_jacobian);

// The VTU file of the grid: points, cells, the arrays (the displacement and
// von Mises when the grid has them; options' certified bounds when given).
void write_grid(std::ostream& out, const Grid& g, const VtuOptions& options);

// Per element of the patch (u fastest, then v, then w), the smallest scaled
// Jacobian at the element's (p + 1)^3 equispaced nodes (corners included): a
// sample, not a bound (igaprep check certifies).
std::vector<double> element_min_scaled_jacobians(const spline::Patch& p);

}  // namespace igaprep::exporter::detail
