#pragma once
// The 2D polycube parameterization of M0trim (seed paper, section 4.2): four
// corners on every boundary loop, an axis-aligned rectilinear domain (the
// outer loop a W x H rectangle, every inner loop a rectangular hole), u and v
// harmonic (cotangent Laplacian) with every boundary segment between two
// corners iso-parametric in u or v, and the domain cut into rectangles by
// extending the holes' sides. Each step is its own function; polycube_2d()
// runs them in order.
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::param {

// An orthonormal frame of a roughly flat sheet: e1 its longest principal
// direction, normal its mean (area-weighted) face normal, e2 = normal x e1.
struct SheetFrame {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero(), e1 = Eigen::Vector3d::UnitX(), e2 = Eigen::Vector3d::UnitY(),
                  normal = Eigen::Vector3d::UnitZ();
};
SheetFrame sheet_frame(const mesh::TriMesh& sheet);

// Side of the domain (outer rectangle or hole) a boundary segment maps to:
// Bottom/Top are iso-v (v = vmin / vmax), Left/Right iso-u (u = umin / umax).
enum class DomainSide { Bottom = 0, Right = 1, Top = 2, Left = 3 };
const char* to_string(DomainSide side);

struct PolycubeLoop {
  std::vector<int> vertices;          // the boundary loop, oriented as the sheet's boundary (sheet on the left)
  bool outer = false;                 // the outer rectangle (else a hole)
  std::array<int, 4> corners{};       // positions in `vertices`, increasing
  std::array<DomainSide, 4> sides{};  // side of segment k, from corner k to corner k + 1 (cyclically)
};

// Splits every interior edge whose two ends are boundary vertices (the inner
// edge of an "ear", a triangle with two boundary edges, or a chord across the
// sheet) at its midpoint: such a triangle's three vertices could otherwise land
// on one straight side of the domain (a zero-area image).
// Inputs/outputs: the sheet; new vertices are appended (edge midpoints).
// Returns the number of edges split.
int split_boundary_ears(mesh::TriMesh& sheet);

// Inputs: sheet, its boundary loops (analyze_sheet), frame. Output: one
// PolycubeLoop per loop, the outer one being the loop of largest signed area
// around frame.normal. Corners: for each loop, the vertices farthest along the
// frame's four diagonal directions (+-e1 +-e2) from the loop's centroid; when
// these are not four distinct corners in order with each segment at least 5 %
// of the loop's length, four corners evenly spread by arc length instead.
std::vector<PolycubeLoop> automatic_corners(const mesh::TriMesh& sheet, const std::vector<std::vector<int>>& loops,
                                            const SheetFrame& frame);

// Inputs: as above, and points: each snapped to the nearest boundary vertex;
// every loop must receive exactly four. Throws bad_input naming the loop
// otherwise, or when two points snap to one vertex.
std::vector<PolycubeLoop> corners_from_points(const mesh::TriMesh& sheet, const std::vector<std::vector<int>>& loops,
                                              const std::vector<Eigen::Vector3d>& points, const SheetFrame& frame);

// A hole corner is a reflex (270 degree) corner of the domain: it needs at
// least three triangles around it, or its fan cannot open without folding.
// Splits the edges opposite the corner in its fan (interior edges only) until
// every hole corner has at least min_fan triangles. Only interior vertices are
// added (appended), so the loops stay valid. Returns the number of splits.
int refine_hole_corners(mesh::TriMesh& sheet, const std::vector<PolycubeLoop>& loops, int min_fan = 4);

struct RectilinearDomain {
  double width = 0.0, height = 0.0;   // the outer rectangle [0, width] x [0, height]
  std::vector<Eigen::Vector4d> holes;  // one per inner loop, in loop order: (umin, vmin, umax, vmax)
  std::vector<int> hole_loop;          // index into the loops of each hole
};

// Inputs: sheet, loops with corners. Output: the domain. W and H are the mean
// 3D lengths of the outer loop's opposite segments; each hole gets the mean
// lengths of its own opposite segments, centred where a harmonic map of the
// sheet with the outer loop fixed on the rectangle and the holes free puts its
// loop; holes are shrunk together until they keep a gap of 4 % of min(W, H)
// from each other and the outside, and hole sides within 5 % of min(W, H) of
// each other are aligned (fewer, better rectangles).
RectilinearDomain rectilinear_domain(const mesh::TriMesh& sheet, const std::vector<PolycubeLoop>& loops);

struct BoundarySegment {
  int loop = 0;
  DomainSide side = DomainSide::Bottom;
  bool u_iso = false;        // Left/Right: u = value; Bottom/Top: v = value
  double value = 0.0;
  std::vector<int> vertices;  // from its start corner to its end corner, both included
};
std::vector<BoundarySegment> boundary_segments(const std::vector<PolycubeLoop>& loops, const RectilinearDomain& domain);

// (u, v) of every boundary vertex: corners at the domain's corners, the
// vertices of a segment spread on its side by 3D arc length.
// Output: #V x 2 (rows of interior vertices unused), and `fixed` (#V) marks.
Eigen::MatrixXd boundary_uv(const mesh::TriMesh& sheet, const std::vector<BoundarySegment>& segments,
                            std::vector<char>& fixed);

enum class UvWeights { Cotangent, MeanValue };
// u and v solving the Laplace equation with the given weights on the free
// vertices, fixed at the boundary (values from boundary_uv).
Eigen::MatrixXd harmonic_uv(const mesh::TriMesh& sheet, const Eigen::MatrixXd& fixed_uv,
                            const std::vector<char>& fixed, UvWeights weights);

// Local untangling: each free vertex of a triangle that is not positively
// oriented is moved into the kernel of its one-ring (the points from which
// every opposite ring edge is seen counter-clockwise), found by cyclic
// projection onto those half-planes. A harmonic map can fold next to the
// reflex (hole) corners of the domain, where no convex-combination theorem
// holds. Returns the number of triangles still not positively oriented.
int untangle_uv(const mesh::TriMesh& sheet, Eigen::MatrixXd& uv, const std::vector<char>& fixed, int rounds = 50);

// Per triangle: signed (u, v) area / 3D area (> 0: positively oriented).
Eigen::VectorXd uv_jacobians(const mesh::TriMesh& sheet, const Eigen::MatrixXd& uv);

// The domain cut into rectangles by extending every hole side across the
// whole domain: the cells of the grid of all hole sides and the outer sides
// that lie outside the holes. Each (umin, vmin, umax, vmax). With
// max_aspect > 0, every interval of that grid longer than max_aspect times
// the longest interval across it is cut into equal parts (a long, narrow
// domain, like a propeller's, gets blocks of a sensible shape).
std::vector<Eigen::Vector4d> domain_rectangles(const RectilinearDomain& domain, double max_aspect = 0.0);

struct Polycube2D {
  SheetFrame frame;
  std::vector<PolycubeLoop> loops;
  RectilinearDomain domain;
  std::vector<BoundarySegment> segments;
  Eigen::MatrixXd uv;                    // #V x 2
  std::vector<Eigen::Vector4d> rectangles;
  Eigen::VectorXd jacobian;              // per triangle (uv_jacobians)
  double min_jacobian = 0.0, max_jacobian = 0.0;
  std::string weights;                   // "cotangent" or "mean value" (fallback)
};

// The whole step. Inputs: sheet (M0trim, after split_boundary_ears; refined in
// place at hole corners, see refine_hole_corners), its boundary loops, corner
// points (empty: automatic). Output: the parameterization; cotangent weights first and mean-value weights when some
// triangle is not positively oriented. Throws bad_input when neither gives
// a bijective map (the message suggests other corners or cut loops).
Polycube2D polycube_2d(mesh::TriMesh& sheet, const std::vector<std::vector<int>>& loops,
                       const std::vector<Eigen::Vector3d>& corner_points = {});

}  // namespace igaprep::param
