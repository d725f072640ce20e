#pragma once
// Cut loops (seed paper, section 4.1): g + 1 closed paths on the outer surface
// T1 (genus g) that split it into two connected regions R+ and R-. They become
// the boundary of the midsurface M0. Three sources: a plane (its intersection
// with T1, inserted into T1 as edges), explicit loops (T1 vertex indices), and
// an automatic choice (planes through the centroid across the principal axes).
// Every cut is validated the same way; a bad one is refused with a message that
// says what was wrong and what to give instead.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::param {

struct CutLoops {
  mesh::TriMesh surface;        // T1 with the cut inserted as edges (original vertices keep their indices,
                                // new ones are appended; unchanged faces keep their orientation)
  Eigen::VectorXi face_side;    // #F: +1 in R+, -1 in R-
  Eigen::VectorXi vertex_side;  // #V: +1 / -1 inside R+ / R-, 0 on a loop
  std::vector<std::vector<int>> loops;  // closed vertex cycles (first vertex not repeated), R+ on the left
  int genus = 0;                // of T1, from its Euler characteristic
  std::string source;           // "plane (...)", "loops", "automatic: ..." for reports
};

struct CutPlane {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // R+ is the side it points to
};

// Genus of a closed, connected, oriented surface from V - E + F = 2 - 2g.
int closed_surface_genus(const Eigen::MatrixXi& F);

// Inputs: T1 (closed, oriented outward), the plane, `name` for messages.
// Vertices closer to the plane than snap * (mean edge length) count as on it
// (the loop then passes through them instead of making slivers); where that
// puts every vertex on one side or on the plane (a plate thinner than the
// tolerance) a tenth, a hundredth and no tolerance are tried.
// Output: the validated cut. Throws bad_input when the plane misses T1, lies
// in one of its faces, or the loops are wrong (see validate_cut).
CutLoops cut_by_plane(const mesh::TriMesh& T1, const CutPlane& plane, const std::string& name = "T1",
                      double snap = 0.05);

// Inputs: T1 and a field on its vertices. Output: the cut along the field's
// zero set, inserted into T1 as edges like a plane's (R+ where the field is
// positive; vertices closer to the zero set than snap * (mean edge length),
// judged by the field's slope, are on it). `source` names it in reports.
// Throws bad_input when the field has one sign or the loops are wrong.
CutLoops cut_by_field(const mesh::TriMesh& T1, const Eigen::VectorXd& field, const std::string& name,
                      const std::string& source, double snap = 0.05);

// Inputs: T1, loops as cycles of T1 vertex indices (consecutive vertices must
// share an edge; the last connects to the first). R+ is the region on the left
// of loops[0] as given (the side whose triangles traverse loops[0][0] ->
// loops[0][1]). Output: the validated cut. Throws bad_input naming the loop and
// vertex when a loop is not a closed simple edge path, or when the loops do not
// split T1 into two regions.
CutLoops cut_by_loops(const mesh::TriMesh& T1, const std::vector<std::vector<int>>& loops,
                      const std::string& name = "T1");

// Inputs: T1 and loops drawn as waypoints (at least 3 points per loop, in
// order; R+ lies on the left of the first loop as drawn, seen from outside).
// Each point snaps to the nearest T1 vertex and consecutive ones, the last
// and the first too, are joined by the shortest edge path on T1. The cut is
// then the zero set of the paths' sides smoothed by three rounds of
// neighbour averaging (no staircase along the triangles), or the edge paths
// themselves when the smoothed set is refused. Throws bad_input naming the
// loop when its points snap to fewer than 3 vertices, and as cut_by_loops.
CutLoops cut_by_waypoints(const mesh::TriMesh& T1, const std::vector<std::vector<Eigen::Vector3d>>& waypoints,
                          const std::string& name = "T1");

// Candidate planes for the automatic cut, best first: through the area
// centroid of T1 with the normal along the smallest principal axis of its
// area-weighted covariance, then the middle and largest axes, then the
// smallest axis offset by +-10 % of T1's extent along it.
std::vector<CutPlane> automatic_cut_planes(const mesh::TriMesh& T1);

// Candidates beyond the principal planes: `normals` directions spread evenly
// over a hemisphere (a Fibonacci lattice), each at `offsets` positions evenly
// inside T1's extent along it. Output: the valid cuts, shortest total loop
// length first (short loops cut a solid across its narrow parts, as a person
// would); `tried` counts the planes and `refusals` sums up why the others
// failed (one line per kind of reason, with its count).
struct PlaneFamily {
  std::vector<CutLoops> valid;
  int tried = 0;
  std::vector<std::string> refusals;
};
PlaneFamily cut_plane_family(const mesh::TriMesh& T1, int normals, int offsets, const std::string& name = "T1");

// Total length of a cut's loops.
double loops_length(const CutLoops& cut);

// The first candidate plane whose cut is valid. Throws bad_input listing why
// each candidate failed and suggesting a plane or explicit loops.
CutLoops cut_automatic(const mesh::TriMesh& T1, const std::string& name = "T1");

// Inputs: T1 and a labelling of its faces (+1 / -1). Output: the cut with its
// loops (the edges between + and - faces), after splitting "chords" (T1 edges
// whose two ends lie on loops but that are no loop edge) so that every T1 edge
// with both ends at f = 0 is a loop edge. Throws bad_input when the loops are
// not simple, their number is not g + 1, or R+ or R- is not connected.
CutLoops validate_cut(const mesh::TriMesh& T1, const Eigen::VectorXi& face_side, const std::string& name,
                      const std::string& source);

}  // namespace igaprep::param
