#pragma once
// Tunnel loops of a closed surface and the cuts they give (docs/midsurface.md,
// "Tunnel loops"). A tunnel loop bounds a disk outside the solid: it runs
// round a through-hole (Dey, Li, Sun, Cohen-Steiner 2008). A solid of genus g
// cut at its middle has g of them as cut loops, one round each hole's wall,
// plus the rim between its two sides; this finds the g loops from the
// surface's homology, whatever the holes' directions, and the rim from a
// field on T1 cut along them.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/param/cut_loops.h"

namespace igaprep::param {

// Linking number of two closed polygons (rows are the points in order, the
// last joined to the first): the Gauss integral, summed exactly per pair of
// segments as a signed solid angle. The polygons must not meet.
double linking_number(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b);

struct TunnelLoopOptions {
  int roots = 48;          // base points of the candidate loops, spread by farthest-point sampling
  int tighten_rounds = 2;  // rounds that look for a shorter loop of the same class through the loop's own vertices
};

// Inputs: T1, closed and oriented outward, of genus g >= 1. Output: g vertex
// cycles of T1 (consecutive vertices share an edge), pairwise vertex-disjoint,
// each bounding a disk outside the solid, independent in homology, each the
// shortest found in its class (a hole's waist). Throws bad_input when fewer
// than g such loops are found (no room for disjoint loops on a coarse mesh).
std::vector<std::vector<int>> tunnel_loops(const mesh::TriMesh& T1, const TunnelLoopOptions& options = {});

// The cuts the tunnel loops give: each loop's two sides on T1 take opposite
// signs; for every choice of the signs (the first loop's fixed) a face field
// on T1 cut along the loops has those values beside them, and its zero set
// adds the rim between the two sides. The field is harmonic, and once more
// with the thin sides' pull of opposite faces of thin parts to opposite
// values (thin_sides.h), so that the rim runs along a plate's edge rather
// than across the plate. The valid cuts, shortest total loop length first;
// `refusals` gets why the others were refused.
std::vector<CutLoops> tunnel_loop_cuts(const mesh::TriMesh& T1, const std::vector<std::vector<int>>& loops,
                                       const std::string& name, std::vector<std::string>& refusals);

}  // namespace igaprep::param
