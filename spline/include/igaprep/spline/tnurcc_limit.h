#pragma once
// The limit surface of a cage with equal knot intervals: Catmull-Clark with
// infinitely sharp creases, evaluated by OpenSubdiv in double precision
// (feature-adaptive refinement, Gregory end caps around extraordinary
// vertices). Every value is a linear combination of the cage's points: the
// limit stencils are sparse rows, so a fit solves a linear least-squares
// problem in the cage points.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "igaprep/spline/tnurcc_cage.h"

namespace igaprep::spline {

// A point of the limit surface: a cage face and (s, t) in [0, 1]^2, s along
// the face's edge 0 (corner 0 -> 1) and t along corner 0 -> 3 (OpenSubdiv's
// ptex coordinates of a quad).
struct LimitLocation {
  int face = 0;
  double s = 0.0, t = 0.0;
};

using StencilMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// Rows: locations; columns: cage points. Derivatives only when asked.
struct LimitStencils {
  StencilMatrix value, ds, dt, dss, dst, dtt;
};

struct LimitOptions {
  int isolation_level = 6;  // adaptive refinement around irregular features
  bool first_derivatives = true;    // ds, dt (normals)
  bool second_derivatives = false;  // dss, dst, dtt (curvature); implies the first
};

// The options with values only (no derivatives): what a fit or a distance needs.
LimitOptions values_only(LimitOptions options);

// Throws bad_input when the cage's intervals are not all equal (OpenSubdiv
// has uniform rules only; non-uniform refinement is tnurcc_refine.h's) or
// a location lies outside its face.
LimitStencils limit_stencils(const Cage& cage, const std::vector<LimitLocation>& at,
                             const LimitOptions& options = {});

// Values at the stencils' locations for the given cage points (#V x 3).
struct LimitValues {
  Eigen::MatrixXd point, normal;  // unit normals, oriented like the faces (outward)
  Eigen::VectorXd mean_curvature;  // positive where the surface bulges outward; empty without 2nd derivatives
};
LimitValues limit_values(const LimitStencils& stencils, const Eigen::MatrixXd& cage_points);

// An n x n grid of locations per face, corners of the grid included when
// `include_ends` (then neighbouring faces' grids share their border points),
// else at the centres of an n x n split.
std::vector<LimitLocation> face_grid(const Cage& cage, int n, bool include_ends);

// The location on face f at fraction a along its edge k (corner k -> k + 1).
LimitLocation edge_location(int face, int k, double a);

}  // namespace igaprep::spline
