#pragma once
// BEXT 2.0 ASCII Bezier-extraction file (the geometry file of LS-DYNA's
// *IGA_INCLUDE_BEZIER, also written by Coreform Cubit). Layout as written
// here (docs/export-formats.md says which parts could not be checked
// against the vendors' specification):
//
//   B E X T 2.0
//   $ comment lines
//   NUMNOD NUMEL NUMCV 0
//   x y z w                      NUMNOD lines: global control points
//                                (Cartesian, weight; interface points shared)
//   NBLOCK                       element blocks, one per patch family
//                                (patches with the same degrees)
//   ETYPE NEL NNPE NCVPE PR PS PT   per block
//   per element of each block, in block order:
//     $ patch P element EU EV EW     (comment)
//     NNPE global node ids (1-based, 10 per line)
//     NCVPE coefficient-vector ids (1-based, 10 per line)
//   NDCVB                        dense coefficient-vector blocks (= NBLOCK)
//   NCV NCVC                     per block: vectors, components per vector
//   NCV vectors of NCVC numbers (5 per line): the rows of the element's
//   extraction operator C_e (local function -> Bernstein coefficients, u
//   fastest), so the element's Bernstein points are C_e^T times its nodes
//   (in homogeneous coordinates for NURBS).
#include <ostream>
#include <string>

#include "igaprep/spline/multipatch.h"

namespace igaprep::exporter {

void write_bext(const spline::MultiPatch& model, std::ostream& out);
void write_bext(const spline::MultiPatch& model, const std::string& path);  // atomic

}  // namespace igaprep::exporter
