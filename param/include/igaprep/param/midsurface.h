#pragma once
// The midsurface sheet M0 (seed paper, section 4.1): the harmonic field f on
// the tet mesh with f = +1 on R+ and -1 on R- of T1 (0 on the cut loops), and
// its zero iso-surface. Its boundary is the cut loops, exactly.
#include <string>

#include <Eigen/Core>

#include "igaprep/mesh/tet_mesh.h"
#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/param/cut_loops.h"

namespace igaprep::param {

// Inputs: tets whose first cut.surface.V.rows() vertices are the vertices of
// cut.surface in order (as mesh::tetrahedralize makes them when cut.surface
// is T1); the cut. Output: f (#tets.V) harmonic, f = vertex_side on T1.
// Throws bad_input when the tet mesh does not start with T1's vertices.
Eigen::VectorXd midsurface_field(const mesh::TetMesh& tets, const CutLoops& cut);

// Splits every tet edge that joins two loop vertices without being a loop edge
// (such an edge lies inside the solid) at its midpoint, so that f = 0 holds on
// no tet edge but the loop edges and M0 stays a manifold along its boundary.
// New vertices are appended (T1's vertices keep their indices); returns the
// number of edges split.
int split_loop_chords(mesh::TetMesh& tets, const CutLoops& cut);

struct Midsurface {
  mesh::TriMesh mesh;       // M0, triangles oriented towards increasing f (normal into R+'s side)
  Eigen::MatrixXi edge;     // #V x 2 tet vertices of the edge each vertex lies on (a, a for a tet vertex at f = 0)
  Eigen::VectorXd t;        // #V: position along that edge
  Eigen::VectorXi tet;      // #F: the tet each triangle lies in
  Eigen::VectorXd field;    // the field that was contoured (f with near-zero free values snapped to 0)
  int snapped = 0;          // free vertices whose value was snapped to 0
  int settled = 0;          // free vertices next to a loop edge whose sign changed (settle_loop_edge_fans)
  std::vector<std::vector<int>> boundary_loops;  // of mesh, oriented as its boundary
};

// Inputs: tets, f, the number of T1 vertices (the Dirichlet vertices, at the
// start of tets.V), snap: a free vertex whose value is so close to 0 that an
// edge of it would be cut within snap of its length from it is snapped to 0
// (no slivers); vertices at exactly 0 are vertices of M0, so the loop vertices
// are M0's boundary, exactly. Round each loop edge the signs of the free
// vertices must change once between its two faces on T1; those that do not
// (a discrete harmonic f need not be monotone there) change sign, the fewest
// by |f|, so that the loop edge bounds one triangle of M0. Output: the zero
// set as a triangle sheet.
// Throws bad_input when four vertices of one tet are at 0 (naming where).
Midsurface zero_sheet(const mesh::TetMesh& tets, const Eigen::VectorXd& f, Eigen::Index num_fixed, double snap);

// The whole step: f, its zero sheet, checked to be a single manifold sheet of
// genus 0 with g + 1 boundary loops, all on T1 (retrying with snap 0 when the
// snapped sheet is not). Throws bad_input saying what is wrong with M0.
Midsurface extract_midsurface(const mesh::TetMesh& tets, const CutLoops& cut, const Eigen::VectorXd& f,
                              double snap = 0.02);

// Quality of the cut (section 4.1): from every T1 vertex off the loops, the
// length of the +grad f (from R-) or -grad f (from R+) path through the tets
// to M0 (f = 0).
struct PathLengthStats {
  int traced = 0;     // paths started
  int reached = 0;    // paths that reached f = 0
  double mean = 0.0, variance = 0.0, min = 0.0, max = 0.0;  // over the paths that reached it
};
PathLengthStats midsurface_path_lengths(const mesh::TetMesh& tets, const Eigen::VectorXd& f, const CutLoops& cut);

}  // namespace igaprep::param
