#pragma once
// One step of global refinement of a cage, written out here (OpenSubdiv is
// its oracle in the tests): every face split into four, Catmull-Clark's
// rules for equal knot intervals, infinitely sharp creases and the cage's
// border as creases (a border vertex with one face a corner), the knot
// intervals halved so that opposite edges stay equal. The refined cage has
// the same limit surface.
#include <Eigen/Core>

#include "igaprep/spline/tnurcc_cage.h"

namespace igaprep::spline {

// Child vertices: one per face (first), one per edge, one per vertex, in the
// parent's orders. Child face 4 f + k holds corner k of parent face f:
// (vertex k, edge k, face, edge k - 1), so its (s, t) run along parent
// edges k and k - 1. Throws bad_input for unequal knot intervals (the
// non-uniform rules of NURSS are not written yet) or a semi-sharp edge.
Cage refine_cage(const Cage& cage);

// The limit position of every cage vertex by Catmull-Clark's masks: a
// smooth vertex of valence n (n^2 v + 4 sum of its edge neighbours + sum of
// its faces' opposite corners) / (n (n + 5)), a crease vertex (a + 4 v + b)
// / 6, a corner v. Same refusals as refine_cage.
Eigen::MatrixXd limit_positions(const Cage& cage);

}  // namespace igaprep::spline
