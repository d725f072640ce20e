#pragma once
// Tetrahedralization of nested closed surfaces T1..Tn (outermost first) as one
// piecewise linear complex with TetGen, a material per tet and every input
// triangle kept as a marked tet face.
#include <vector>

#include "igaprep/mesh/tet_mesh.h"
#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::mesh {

struct TetgenOptions {
  double radius_edge_ratio = 1.5;  // TetGen -q bound; 0 switches quality refinement off
  double max_volume = 0.0;         // TetGen -a bound; 0 = no bound. With -Y (input
                                   // triangles never split) tets touching an input
                                   // surface may exceed it somewhat.
  bool quiet = true;               // false: copy TetGen's output to stdout
  // Refused before TetGen runs when max_volume would make more tets than
  // this (at least T1's volume / max_volume); TetGen takes about 1 GB per
  // 5 million tets.
  double max_tets = 2e7;
};

// Inputs: `surfaces` are closed, validated, nested (T1 outermost);
// `embedded` are open or closed surfaces strictly inside T1 to keep as tet
// faces too (the midsurface later). Surfaces keep their triangles exactly
// (no Steiner points on them).
// Output: a TetMesh with material i between T(i+1) and T(i+2) (0-based:
// material 0 between T1 and T2, ..., n-1 inside Tn); F/F_marker list every
// input triangle with marker = surface index (0..n-1), then every embedded
// triangle with marker n + k for embedded surface k.
// Materials come from a flood fill across tet faces not on T1..Tn, each region
// classified by exact inside tests (CGAL), so embedded closed surfaces do not
// split a material. Tets are positively oriented; deterministic.
// Throws Error(BadInput) naming the surfaces when two of them intersect
// (checked exactly before meshing), and with TetGen's own reason when it
// fails; TetGen runs in a child process, so its crashes and exit() calls on
// bad input cannot take the caller down.
TetMesh tetrahedralize(const std::vector<TriMesh>& surfaces, const std::vector<TriMesh>& embedded = {},
                       const TetgenOptions& options = {});

}  // namespace igaprep::mesh
