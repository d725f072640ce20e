#pragma once
// One step of global refinement of a cage, written out here: every face
// split into four by the NURCC rules (knot intervals on edges, opposite
// edges of a face equal; non-uniform cubic B-spline knot insertion at the
// middle of every interval, Catmull-Clark's rules when the intervals are
// equal, where OpenSubdiv is the tests' oracle), infinitely sharp creases
// and the cage's border as creases (a border vertex with one face a
// corner), every interval halved so that opposite edges stay equal. The
// refined cage has the same limit surface.
#include <Eigen/Core>

#include "igaprep/spline/tnurcc_cage.h"

namespace igaprep::spline {

// Child vertices: one per face (first), one per edge, one per vertex, in the
// parent's orders. Child face 4 f + k holds corner k of parent face f:
// (vertex k, edge k, face, edge k - 1), so its (s, t) run along parent
// edges k and k - 1. Throws bad_input for a face whose opposite edges carry
// different intervals or a semi-sharp edge.
Cage refine_cage(const Cage& cage);

// The limit position of every cage vertex by Catmull-Clark's masks: a
// smooth vertex of valence n (n^2 v + 4 sum of its edge neighbours + sum of
// its faces' opposite corners) / (n (n + 5)), a crease vertex (a + 4 v + b)
// / 6, a corner v. Equal intervals only (throws bad_input otherwise).
Eigen::MatrixXd limit_positions(const Cage& cage);

}  // namespace igaprep::spline
