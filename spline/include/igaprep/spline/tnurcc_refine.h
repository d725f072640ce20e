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
#include "igaprep/spline/tnurcc_limit.h"

namespace igaprep::spline {

// Child vertices: one per face (first), one per edge, one per vertex, in the
// parent's orders. Child face 4 f + k holds corner k of parent face f:
// (vertex k, edge k, face, edge k - 1), so its (s, t) run along parent
// edges k and k - 1. Throws bad_input for a face whose opposite edges carry
// different intervals or a semi-sharp edge.
Cage refine_cage(const Cage& cage);

// The same step with its weights: child.points == weights * cage.points
// (a row per child vertex, a column per cage vertex, each row summing to 1).
struct CageRefinement {
  Cage child;
  StencilMatrix weights;
};
CageRefinement refinement(const Cage& cage);

// The limit position of every cage vertex, for any intervals that
// refine_cage takes, read off the cage refined once: at a smooth vertex of
// valence 4 the tensor product of the cubic B-spline's masks at its knots,
// at a crease vertex the curve's mask along the crease, at a smooth
// extraordinary vertex the left eigenvector (eigenvalue 1) of its ring's
// stationary refinement matrix applied to the ring, a corner stays. With
// equal intervals these are Catmull-Clark's masks ((n^2 v + 4 sum of edge
// neighbours + sum of opposite face corners) / (n (n + 5)), (a + 4 v + b) / 6).
Eigen::MatrixXd limit_positions(const Cage& cage);

// The weights behind limit_positions: limit_positions(cage) ==
// limit_position_weights(cage) * cage.points.
StencilMatrix limit_position_weights(const Cage& cage);

// Two limit tangents at every smooth cage vertex, as weights over the cage
// points, first x second pointing out of the surface (faces counter-
// clockwise seen from outside): at valence 4 the derivatives along spokes
// 0 and 1 per unit of knot parameter (the B-spline's), at an extraordinary
// vertex the ring's subdominant left eigenvectors (a basis of the tangent
// plane, not derivatives). Crease vertices and corners, where the tangent
// plane is one-sided, get zero rows.
struct VertexTangentWeights {
  StencilMatrix first, second;
};
VertexTangentWeights limit_tangent_weights(const Cage& cage);

// Limit points of any cage refine_cage takes, on a dyadic grid: each face's
// (2^levels + 1)^2 locations (s, t) = (i, j) / 2^levels, s fastest (grids of
// neighbouring faces share their border points), with their weights over
// the cage points: the refinement's weights `levels` times, then the limit
// positions' (exact limit points, also for unequal intervals, where
// OpenSubdiv's limit is not the NURCC's).
struct DyadicLimit {
  int levels = 0;
  std::vector<LimitLocation> at;
  StencilMatrix weights;  // a row per location
};
DyadicLimit dyadic_limit(const Cage& cage, int levels);

}  // namespace igaprep::spline
