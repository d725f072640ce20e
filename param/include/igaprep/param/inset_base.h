#pragma once
// The base surface the volume decomposition is built on: M0trim inset by a
// distance d in its rectilinear (u, v) domain (the outer rectangle shrunk by
// d, every hole grown by d), cut exactly along those lines. Like the paper's
// M = {b >= m0} (section 4.4) it is the midsurface retracted from Tn, but its
// boundary has real corners where the domain has them: a smooth boundary with
// marked corners (the b-field M) makes the volume patches above and below M
// flat (180 degrees) at those corners, a zero scaled Jacobian.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/param/polycube_2d.h"

namespace igaprep::param {

struct InsetBase {
  mesh::TriMesh mesh;          // M: the part of M0trim inside the inset domain
  Eigen::MatrixXd uv;          // #M.V x 2, in the inset domain's coordinates
  RectilinearDomain domain;    // about [0, W - 2d] x [0, H - 2d] with the grown holes: each cut line is
                               // moved by up to 0.2 mean (u, v) edges, away from the sheet's vertices
  double inset = 0.0;          // the nominal d, in (u, v) units (= 3D arc length along the domain's sides)
  int smoothing = 0;           // smoothing rounds used: fewer than asked where more made M intersect itself
};

// Whether a triangle sheet crosses itself (mesh::find_self_intersections:
// exact predicates; triangles that share a vertex or an edge only do not
// count). Throws Error(BadInput) starting with `name` when that cannot be
// decided: the sheet is not an oriented 2-manifold (analyze_sheet says how).
bool sheet_self_intersects(const mesh::TriMesh& sheet, const std::string& name);

// Inputs: a sheet and its (u, v), a value c, the axis (0: u, 1: v). Splits
// every triangle that the line uv(axis) = c crosses (orientation kept; new
// vertices interpolated in 3D and (u, v) along the crossing edges, shared by
// the two triangles of an edge). Vertices within snap of the line are put on
// it in (u, v) first (no slivers), except those flagged in `unsnapped`
// (vertices on another line). Returns the number of edges split.
int split_sheet_along_line(mesh::TriMesh& sheet, Eigen::MatrixXd& uv, int axis, double c, double snap,
                           const std::vector<char>& unsnapped = {});

// The narrowest band of a domain: its width, its height, the gaps between
// holes and between a hole and the outside.
double narrowest_band(const RectilinearDomain& domain);

// Collapses every edge shorter than min_length (3D) whose triangles stay
// positively oriented in (u, v) after moving one end onto the other; a
// pinned vertex is never moved, except onto a vertex at the same (u, v):
// an edge of no length in (u, v) is collapsed whatever its 3D length, and
// so is the shortest (u, v) edge of a triangle turned over in (u, v).
// Returns the number of edges collapsed.
int collapse_short_edges(mesh::TriMesh& sheet, Eigen::MatrixXd& uv, const std::vector<char>& pinned, double min_length);

// Inputs: M0trim with its 2D polycube, `inset` in (0, 1): d = inset x half the
// narrowest band of the domain (its width, its height, and the gaps between
// holes and between a hole and the outside); rounds of Taubin smoothing of
// the 3D positions along the normals (the domain's corners fixed; halved
// until M does not intersect itself, InsetBase::smoothing). Output: the inset sheet.
// Throws bad_input (the inset and the corners are the user's to change)
// when the result is not one sheet with one boundary loop per domain boundary.
InsetBase inset_base_surface(const mesh::TriMesh& sheet, const Polycube2D& polycube, double inset, int smoothing);

// Taubin smoothing (lambda 0.5, mu -0.53) of a sheet's vertices along their
// normals (no tangential drift under the (u, v) map); `fixed` vertices stay.
void smooth_sheet(mesh::TriMesh& sheet, const std::vector<char>& fixed, int rounds);

}  // namespace igaprep::param
