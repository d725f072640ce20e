#pragma once
// The 2D polycube parameterization of M0trim (seed paper, section 4.2): four
// corners on every boundary loop, an axis-aligned rectilinear domain (the
// outer loop a W x H rectangle with an arm out of it per lobe of the sheet,
// every inner loop a rectangular hole), u and v harmonic (cotangent
// Laplacian) with every boundary segment between two corners iso-parametric
// in u or v, and the domain cut into rectangles by extending the holes' and
// the arms' sides. Each step is its own function; polycube_2d() runs them in
// order.
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

// A lobe of the outer loop as an arm of the domain: the positions in the
// loop of its four corners in loop order (the neck's first end, the tip's two
// corners, the neck's second end), all inside one segment, and the arm's
// size in 3D: as long as the lobe reaches from its neck, as wide as its area
// over that (at least the neck's width).
struct LoopArm {
  std::array<int, 4> corners{};
  double width = 0.0, length = 0.0;
  // The neck across the sheet: a shortest edge path from corners[0] to
  // corners[3] through the sheet's interior, fixed on the line the arm
  // joins the rectangle by, so that the rectangle and each arm are mapped
  // each onto a convex domain (bijective). Set by polycube_2d.
  std::vector<int> neck_path;
};

struct PolycubeLoop {
  std::vector<int> vertices;          // the boundary loop, oriented as the sheet's boundary (sheet on the left)
  bool outer = false;                 // the outer rectangle (else a hole)
  std::array<int, 4> corners{};       // positions in `vertices`, increasing
  std::array<DomainSide, 4> sides{};  // side of segment k, from corner k to corner k + 1 (cyclically)
  // The outer loop's lobes (sheet_lobes.h), each an arm of the domain,
  // ordered along the loop from corner 0.
  std::vector<LoopArm> arms;
};

// Splits every interior edge whose two ends are boundary vertices (the inner
// edge of an "ear", a triangle with two boundary edges, or a chord across the
// sheet) at its midpoint: such a triangle's three vertices could otherwise land
// on one straight side of the domain (a zero-area image).
// Inputs/outputs: the sheet; new vertices are appended (edge midpoints).
// Returns the number of edges split.
int split_boundary_ears(mesh::TriMesh& sheet);

// Inputs: sheet, its boundary loops (analyze_sheet), frame, whether the outer
// loop's lobes get arms. Output: one PolycubeLoop per loop, the outer one
// being the loop of largest signed area around frame.normal. Corners: for
// each loop, the vertices farthest along the frame's four diagonal directions
// (+-e1 +-e2) from the loop's centroid, a lobe's boundary left out; when
// these are not four distinct corners in order with each segment at least 5 %
// of the loop's length, four corners evenly spread by arc length instead (and
// no arms). An arm's tip corners split the lobe's boundary in the arm's
// proportions: side, tip, side as length, width, length.
std::vector<PolycubeLoop> automatic_corners(const mesh::TriMesh& sheet, const std::vector<std::vector<int>>& loops,
                                            const SheetFrame& frame, bool arms = true);

// Inputs: as above, and points: each snapped to the nearest boundary vertex;
// every loop must receive exactly four. Throws bad_input naming the loop
// otherwise, or when two points snap to one vertex.
std::vector<PolycubeLoop> corners_from_points(const mesh::TriMesh& sheet, const std::vector<std::vector<int>>& loops,
                                              const std::vector<Eigen::Vector3d>& points, const SheetFrame& frame);

// A hole corner, like an arm's neck, is a reflex (270 degree) corner of the
// domain: it needs at least three triangles around it, or its fan cannot
// open without folding. Splits the edges opposite the corner in its fan
// (interior edges only) until every reflex corner has at least min_fan
// triangles. Only interior vertices are
// added (appended), so the loops stay valid. Returns the number of splits.
int refine_hole_corners(mesh::TriMesh& sheet, const std::vector<PolycubeLoop>& loops, int min_fan = 4);

// An arm of the domain: a rectangle on a side of the outer rectangle, out of it.
struct DomainArm {
  DomainSide side = DomainSide::Bottom;
  // Along the side in the outer loop's direction (bottom: +u, right: +v,
  // top: -u, left: -v), from the side's first corner; from < to.
  double from = 0.0, to = 0.0;
  double length = 0.0;  // out of the rectangle
};

struct RectilinearDomain {
  double width = 0.0, height = 0.0;   // the outer rectangle [0, width] x [0, height]
  std::vector<Eigen::Vector4d> holes;  // one per inner loop, in loop order: (umin, vmin, umax, vmax)
  std::vector<int> hole_loop;          // index into the loops of each hole
  std::vector<DomainArm> arms;         // in the outer loop's order from its corner 0 (PolycubeLoop::arms)
};

// An arm as a box (umin, vmin, umax, vmax), and back (the arm on that side
// of a domain whose outer rectangle is width x height).
Eigen::Vector4d arm_box(const RectilinearDomain& domain, const DomainArm& arm);
DomainArm arm_from_box(DomainSide side, const Eigen::Vector4d& box, double width, double height);

// Inputs: (u, v) point, domain. Output: whether it lies inside the domain
// (in the outer rectangle or an arm, and in no hole), boundary excluded.
bool inside_domain(const RectilinearDomain& domain, const Eigen::Vector2d& p);

// The corners of the outer boundary along one side of the outer rectangle in
// the loop's direction: the side's first corner, each arm's four corners
// (neck, tip, tip, neck), the side's last corner.
std::vector<Eigen::Vector2d> side_walk(const RectilinearDomain& domain, DomainSide side);

// Inputs: sheet, loops with corners. Output: the domain. W and H are the mean
// 3D lengths of the outer loop's opposite segments (a lobe's boundary counted
// as its arm's width); an arm has its LoopArm size (the width scaled as its
// segment is onto its side); each hole gets the mean
// lengths of its own opposite segments, centred where a harmonic map of the
// sheet with the outer loop fixed on the rectangle and the holes free puts its
// loop; holes are shrunk together until they keep a gap of 4 % of min(W, H)
// from each other and the outside, and hole sides within 5 % of min(W, H) of
// each other are aligned (fewer, better rectangles); then any box sides
// within 1 % of min(W, H) of each other are merged (merge_close_sides).
RectilinearDomain rectilinear_domain(const mesh::TriMesh& sheet, const std::vector<PolycubeLoop>& loops);

// Sides of the domain's holes and arms that lie within `tolerance` of each
// other across the domain move onto one line (their mean, or the outer
// rectangle's side when that is one of them): the grid of all sides
// (domain_rectangles) would otherwise cut a sliver of rectangles between
// them, whose blocks fold (the hand: two fingers' sides 0.0008 apart in a
// domain 0.9 wide). Two sides of one box are never merged.
void merge_close_sides(RectilinearDomain& domain, double tolerance);

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

// The share of the sheet's 3D area in triangles whose (u, v) Jacobian is
// under `factor` times the area-weighted median: the part a map squeezes (a
// lobe pressed into a sliver, whose volume the blocks then lose).
double squeezed_share(const mesh::TriMesh& sheet, const Eigen::VectorXd& jacobian, double factor = 0.1);

// The domain cut into rectangles by extending every hole side and arm side
// across the whole domain: the cells of the grid of all hole sides, arm sides
// and the outer sides that lie inside the domain. Each (umin, vmin, umax, vmax). With
// max_aspect > 0, every interval of that grid longer than max_aspect times
// the longest interval across it is cut into equal parts (a long, narrow
// domain, like a propeller's, gets blocks of a sensible shape). Lines in
// `extra` (u = x and v = y, strictly inside the domain) cut it as well.
struct GridLines {
  std::vector<double> u, v;
};
std::vector<Eigen::Vector4d> domain_rectangles(const RectilinearDomain& domain, double max_aspect = 0.0,
                                               const GridLines& extra = {});

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
  int lobes = 0;                         // lobes found on the outer loop
  bool arms_dropped = false;             // they were found, but the map was made without their arms
  // When the map folded next to the holes' corners: sheet paths from each
  // hole corner straight out to the first loop or earlier path met, fixed on
  // their lines so that every part of the domain is convex (empty otherwise).
  std::vector<std::vector<int>> hole_cuts;
  std::string arms_dropped_reason;       // why
};

// Whether every segment between the outer loop's corners and its arms'
// corners has at least one edge. Two lobes found side by side can share a
// neck's corner (seen on the hand of ../shared/models cut by its palm
// plane), which would leave a segment of no length between their arms:
// polycube_2d then maps without arms.
bool arms_apart(const std::vector<PolycubeLoop>& loops);

// A harmonic map onto a domain with holes may fold next to the holes'
// reflex corners. Cut from every hole corner straight out, turning the same
// way round each hole (a pinwheel: bottom-left down, bottom-right right,
// top-right up, top-left left), to the first thing met (the outer
// rectangle, another hole or an earlier cut): every part of the domain is
// then a rectangle, convex, and a convex-combination map onto each is
// bijective (Tutte, Floater) once the cuts' sheet paths are fixed on their
// lines.
//
// Finds a sheet path per hole corner into pc.hole_cuts (the corner first,
// ending on the outer loop, a hole's loop or an earlier path), each
// touching no boundary vertex or earlier path between its ends and
// following the cut's line in a map that cannot fold (the sheet with its
// holes filled, mapped by mean-value weights onto the outer rectangle). A
// corner whose cut finds no path is left uncut. For a domain with holes and
// no arms. False when no cut was found.
bool find_hole_cuts(const mesh::TriMesh& sheet, Polycube2D& pc);

// Fixes each cut's vertices on the straight line between its ends' (u, v)
// (set before: boundary vertices, earlier cuts), spread by 3D arc length.
void fix_hole_cuts(const mesh::TriMesh& sheet, const Polycube2D& pc, Eigen::MatrixXd& uv, std::vector<char>& fixed);

// The (u, v) map with those cuts (pc.loops and pc.domain set, no arms): the
// cuts found, interior edges between two fixed vertices split (sheet gets
// vertices appended), u and v made as by polycube_2d. False when no cut was
// found (pc unchanged).
bool map_with_hole_cuts(mesh::TriMesh& sheet, Polycube2D& pc);


// The whole step. Inputs: sheet (M0trim, after split_boundary_ears; refined in
// place at reflex corners, see refine_hole_corners), its boundary loops, corner
// points (empty: automatic, with an arm per lobe when `arms`). Output: the
// parameterization; cotangent weights first and mean-value weights when some
// triangle is not positively oriented; without arms when the map with them
// folds. Throws bad_input when nothing gives a bijective map (the message
// suggests other corners or cut loops).
Polycube2D polycube_2d(mesh::TriMesh& sheet, const std::vector<std::vector<int>>& loops,
                       const std::vector<Eigen::Vector3d>& corner_points = {}, bool arms = true);

}  // namespace igaprep::param
