#pragma once
// VTU (VTK XML UnstructuredGrid, file version 2.2) with one Bezier hexahedron
// (VTK_BEZIER_HEXAHEDRON = 79) per Bezier element of every patch, for
// ParaView and VTK >= 9. Points are the element's Bernstein control points
// from the spline module's Bezier extraction, in the order of
// vtkHigherOrderHexahedron::PointIndexFromIJK (corners, edges, faces,
// interior). A model's points are shared between cells where they coincide
// within a material (a solve result's are not: its stress is discontinuous).
//
// Data arrays:
//  - point data "RationalWeights" (named in <PointData RationalWeights=...>),
//    1 for B-spline patches;
//  - cell data "HigherOrderDegrees" (3 components, named in <CellData
//    HigherOrderDegrees=...>), "material" and "patch" (Int32), "element"
//    (Int32, the element's index per direction in its patch) and
//    "min_scaled_jacobian" (the smallest at the element's (p + 1)^3
//    equispaced nodes: a sample for looking, `igaprep check` certifies);
//  - point data "material" and "patch" too: VTK's cutter interpolates
//    higher-order cell data into nonsense (values of +-2e9 on a slice),
//    point data constant over each cell slices exactly;
//  - when the patches carry a displacement: point data "displacement", the
//    displacement's Bernstein coefficients on the element (exact: the same
//    rational Bernstein basis as the geometry), and "von_mises", the von Mises
//    stress of the isotropic linear-elastic material (E, nu of the patch's
//    material) evaluated at the element's equispaced nodes t = (i/p_u, j/p_v,
//    k/p_w) and interpolated there by the element's (rational) Bernstein
//    basis, so VTK reproduces the exact stress at those nodes.
#include <array>
#include <ostream>
#include <string>
#include <vector>

#include "igaprep/spline/extraction_model.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::exporter {

struct VtuOptions {
  bool binary = true;  // appended raw binary data; false: ASCII (readable, larger)
  // Per cell in the writer's order (patches in turn, each element w, v, u
  // with u fastest, as iga_check::certify_model lists them): the certified
  // lower bound of det J, written as cell data "certified_det_lower_bound";
  // empty: not written.
  std::vector<double> certified_lower_bound;
};

// Inputs: model (every degree >= 1). Output: the VTU text on `out`.
void write_vtu_bezier(const spline::MultiPatch& model, std::ostream& out, const VtuOptions& options = {});
void write_vtu_bezier(const spline::MultiPatch& model, const std::string& path,
                      const VtuOptions& options = {});  // atomic

// The same for a model in Bezier-extraction form (a T-spline): one cell per
// element from spline::bernstein_element, cell data "patch" and "element"
// from the element's provenance (-1 and 0 when it has none).
void write_vtu_bezier(const spline::ExtractionModel& model, const std::string& path);  // atomic
void write_vtu_bezier(const spline::ExtractionModel& model, std::ostream& out);

// VTK's point index of Bernstein node (i, j, k) of a hexahedron of the given
// degrees (vtkHigherOrderHexahedron::PointIndexFromIJK, VTK 9 numbering).
int vtk_hex_point_index(int i, int j, int k, const std::array<int, 3>& degrees);

}  // namespace igaprep::exporter
