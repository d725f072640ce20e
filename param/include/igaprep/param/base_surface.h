#pragma once
// The base surface M (seed paper, sections 4.3 and 4.4): the medial axis of
// the rectilinear (u, v) domain of M0trim, its image on M0trim, the harmonic
// field b (1 there, 0 on M0trim's boundary), M = {b >= m0} with (u, v)
// inherited from M0trim, and the corners of M0trim moved along grad b onto M's
// boundary.
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/param/polycube_2d.h"

namespace igaprep::param {

// The medial axis of the domain, at the resolution of the sheet: the sheet
// edges whose two ends have different nearest boundary features (the domain's
// sides and the holes' corners) that do not share a domain vertex. Those are
// the Voronoi boundaries between non-adjacent features, i.e. the medial axis
// without its branches into convex corners (section 4.3).
// Inputs: sheet, its uv, the domain. Output: the sheet vertices at the ends of
// those edges (never a boundary vertex); when none is found (a square domain,
// whose medial axis is one point), the interior vertex deepest in the domain.
std::vector<int> medial_axis_vertices(const mesh::TriMesh& sheet, const Eigen::MatrixXd& uv,
                                      const RectilinearDomain& domain, const std::vector<char>& boundary);

// Inputs: sheet, Dirichlet vertex lists. Output: b (#V) harmonic (cotangent),
// 1 on `medial`, 0 on `boundary`.
Eigen::VectorXd base_field(const mesh::TriMesh& sheet, const std::vector<int>& medial, const std::vector<int>& boundary);

struct BaseSurface {
  std::vector<int> medial;          // sheet vertices on the medial axis image
  Eigen::VectorXd b;                // on M0trim
  double m0 = 0.0;
  mesh::TriMesh mesh;               // M
  Eigen::MatrixXd uv;               // #M.V x 2, inherited from M0trim
  Eigen::MatrixXi source_edge;      // #M.V x 2: M0trim vertices (a, a for a vertex of M0trim) ...
  Eigen::VectorXd source_t;         // ... and the position along that edge
  std::vector<std::vector<int>> boundary_loops;  // of M
  std::vector<std::array<int, 4>> corners;       // per M0trim loop (polycube loop order): M vertex of each corner
  std::vector<int> corner_loop;                  // per M0trim loop: the index of its loop in boundary_loops
  Eigen::MatrixXd corner_traces_end;             // (#loops * 4) x 3: where the grad-b traces ended
};

// Inputs: sheet (M0trim), b, m0 in (0, 1), uv. Output: M = {b >= m0}, its
// triangles clipped at b = m0 (values within 1 % of an edge of m0 snapped to
// it), (u, v) interpolated. Throws bad_input when m0 is out of (0, 1) or M is
// empty.
BaseSurface trim_base_surface(const mesh::TriMesh& sheet, const Eigen::VectorXd& b, double m0,
                              const Eigen::MatrixXd& uv);

// The whole step: medial axis, b, M, its check (single sheet with
// expected_loops boundary loops), and the corners: each M0trim corner traced
// along +grad b to b = m0 and inserted into M's boundary there (or snapped to
// an end of the boundary edge when within 5 % of it).
BaseSurface base_surface(const mesh::TriMesh& sheet, const Polycube2D& polycube, double m0, int expected_loops);

}  // namespace igaprep::param
