// The tools of the volume parameterization: cutting a sheet along (u, v)
// lines and insetting it (inset_base.h), sampling a sheet through its (u, v)
// (sheet_sampler.h), probing a P1 field on tets (field_probe.h), streamline
// columns (streamline_column.h), the base layout (base_layout.h) and the
// option checks of build_volume_param (volume_param.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "igaprep/core/error.h"
#include "igaprep/param/base_layout.h"
#include "igaprep/param/field_probe.h"
#include "igaprep/param/gradient.h"
#include "igaprep/param/inset_base.h"
#include "igaprep/param/polycube_2d.h"
#include "igaprep/param/sheet_sampler.h"
#include "igaprep/param/sheet_topology.h"
#include "igaprep/param/streamline_column.h"
#include "igaprep/param/tet_topology.h"
#include "igaprep/param/volume_param.h"
#include "param/param_meshes.h"

namespace {

using namespace igaprep;
using namespace igaprep::param;

double signed_area(const Eigen::MatrixXd& uv, int a, int b, int c) {
  const Eigen::Vector2d e1 = (uv.row(b) - uv.row(a)).transpose(), e2 = (uv.row(c) - uv.row(a)).transpose();
  return 0.5 * (e1.x() * e2.y() - e1.y() * e2.x());
}

double uv_area(const mesh::TriMesh& m, const Eigen::MatrixXd& uv) {
  double s = 0.0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) s += signed_area(uv, m.F(f, 0), m.F(f, 1), m.F(f, 2));
  return s;
}

double area_3d(const mesh::TriMesh& m) {
  double s = 0.0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    s += 0.5 * (b - a).cross(c - a).norm();
  }
  return s;
}

double min_uv_area(const mesh::TriMesh& m, const Eigen::MatrixXd& uv) {
  double s = std::numeric_limits<double>::infinity();
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) s = std::min(s, signed_area(uv, m.F(f, 0), m.F(f, 1), m.F(f, 2)));
  return s;
}

// Vertices on the sheet's boundary (edges of one triangle).
std::vector<int> boundary_vertices(const mesh::TriMesh& m) {
  std::map<std::pair<int, int>, int> count;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) ++count[std::minmax(m.F(f, k), m.F(f, (k + 1) % 3))];
  std::set<int> b;
  for (const auto& [e, n] : count)
    if (n == 1) b.insert(e.first), b.insert(e.second);
  return {b.begin(), b.end()};
}

// A planar grid sheet on [0, W] x [0, H] (z = 0) with cells of size h, the
// triangles inside `hole` (umin, vmin, umax, vmax) removed.
mesh::TriMesh grid_sheet(double W, double H, double h, const std::vector<Eigen::Vector4d>& holes = {}) {
  const int nx = static_cast<int>(std::lround(W / h)), ny = static_cast<int>(std::lround(H / h));
  mesh::TriMesh m = param_test::square_tris(std::max(nx, ny));
  // square_tris is square: take its cells with i < nx, j < ny, scaled by h.
  const int n = std::max(nx, ny);
  m.V *= h * n;
  std::vector<Eigen::Vector3i> keep;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) c += m.V.row(m.F(f, k)).transpose() / 3.0;
    if (c.x() > W || c.y() > H) continue;
    bool in_hole = false;
    for (const auto& r : holes) in_hole |= c.x() > r(0) && c.x() < r(2) && c.y() > r(1) && c.y() < r(3);
    if (!in_hole) keep.push_back(m.F.row(f).transpose());
  }
  // Drop unused vertices.
  std::vector<int> index(static_cast<std::size_t>(m.V.rows()), -1);
  int count = 0;
  mesh::TriMesh out;
  out.F.resize(static_cast<Eigen::Index>(keep.size()), 3);
  for (std::size_t f = 0; f < keep.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      int& id = index[static_cast<std::size_t>(keep[f](k))];
      if (id < 0) id = count++;
      out.F(static_cast<Eigen::Index>(f), k) = id;
    }
  out.V.resize(count, 3);
  for (std::size_t v = 0; v < index.size(); ++v)
    if (index[v] >= 0) out.V.row(index[v]) = m.V.row(static_cast<Eigen::Index>(v));
  return out;
}

// ---------------------------------------------------------------- split_sheet_along_line

TEST(SplitSheetAlongLine, PlanarGridCutCleanly) {
  mesh::TriMesh m = param_test::square_tris(7, 0.3, 5);
  Eigen::MatrixXd uv = m.V.leftCols(2);
  const Eigen::Index nv0 = m.V.rows();
  for (const auto& [axis, c] : std::vector<std::pair<int, double>>{{0, 0.5}, {1, 0.64}, {0, 0.79}}) {
    const Eigen::Index before_v = m.V.rows();
    const int split = split_sheet_along_line(m, uv, axis, c, 1e-9);
    EXPECT_GT(split, 0);
    ASSERT_EQ(m.V.rows(), before_v + split);  // one new vertex per split edge
    ASSERT_EQ(uv.rows(), m.V.rows());
    EXPECT_GT(min_uv_area(m, uv), 0.0) << "a triangle is not positively oriented after the cut at " << c;
    EXPECT_NEAR(uv_area(m, uv), 1.0, 1e-12);
    EXPECT_NEAR(area_3d(m), 1.0, 1e-12);
    for (Eigen::Index v = before_v; v < m.V.rows(); ++v) {
      EXPECT_EQ(uv(v, axis), c) << "new vertex " << v;
      EXPECT_NEAR((m.V.row(v).leftCols(2) - uv.row(v)).norm(), 0.0, 1e-15);  // interpolated in 3D alike
      EXPECT_EQ(m.V(v, 2), 0.0);
    }
    for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (int k = 0; k < 3; ++k) lo = std::min(lo, uv(m.F(f, k), axis) - c), hi = std::max(hi, uv(m.F(f, k), axis) - c);
      EXPECT_FALSE(lo < 0.0 && hi > 0.0) << "triangle " << f << " crosses the line";
    }
    // Still one oriented manifold disc: the new vertices are shared by both triangles of an edge.
    const SheetTopology topo = analyze_sheet(m.F, m.V.rows());
    EXPECT_EQ(describe_sheet_problem(topo, 1, "cut grid"), "");
    EXPECT_EQ(topo.vertices, m.V.rows());
  }
  EXPECT_GT(m.V.rows(), nv0);
}

TEST(SplitSheetAlongLine, LineThroughVerticesAndSnap) {
  // Unjittered grid: the line x = 3/6 runs along grid edges, nothing is split.
  mesh::TriMesh m = param_test::square_tris(6);
  Eigen::MatrixXd uv = m.V.leftCols(2);
  const Eigen::MatrixXi F0 = m.F;
  EXPECT_EQ(split_sheet_along_line(m, uv, 0, 0.5, 1e-9), 0);
  EXPECT_EQ(m.F, F0);
  EXPECT_EQ(m.V.rows(), 49);

  // A line 1e-4 beyond the grid line x = 1/3 with snap 1e-3: the grid
  // vertices there are put on it in (u, v) and nothing is split.
  const double c = 2.0 / 6.0 + 1e-4;
  EXPECT_EQ(split_sheet_along_line(m, uv, 0, c, 1e-3), 0);
  int on_line = 0;
  for (Eigen::Index v = 0; v < uv.rows(); ++v)
    if (uv(v, 0) == c) {
      ++on_line;
      EXPECT_NEAR(m.V(v, 0), 2.0 / 6.0, 1e-15);  // 3D unchanged
    }
  EXPECT_EQ(on_line, 7);
  EXPECT_GT(min_uv_area(m, uv), 0.0);

  // Without snap the same line crosses every edge from x = 1/3 to x = 1/2:
  // 7 horizontal ones and the 6 cell diagonals.
  mesh::TriMesh m2 = param_test::square_tris(6);
  Eigen::MatrixXd uv2 = m2.V.leftCols(2);
  EXPECT_EQ(split_sheet_along_line(m2, uv2, 0, c, 0.0), 13);
  EXPECT_GT(min_uv_area(m2, uv2), 0.0);
  EXPECT_NEAR(uv_area(m2, uv2), 1.0, 1e-12);
}

// A second line half a snap beyond one already cut: the first line's
// vertices stay on it when flagged (else they snap onto the second and
// the triangles between the two lose their area), and the second is cut.
TEST(SplitSheetAlongLine, FlaggedVerticesStayOnTheirLine) {
  mesh::TriMesh m = param_test::square_tris(6);
  Eigen::MatrixXd uv = m.V.leftCols(2);
  const double first = 2.0 / 6.0, second = first + 5e-4;
  std::vector<char> on_first(static_cast<std::size_t>(uv.rows()), 0);
  for (Eigen::Index v = 0; v < uv.rows(); ++v) on_first[static_cast<std::size_t>(v)] = uv(v, 0) == first;
  EXPECT_EQ(split_sheet_along_line(m, uv, 0, second, 1e-3, on_first), 13);  // 7 rows and 6 diagonals
  int still_on_first = 0;
  for (Eigen::Index v = 0; v < static_cast<Eigen::Index>(on_first.size()); ++v) still_on_first += uv(v, 0) == first;
  EXPECT_EQ(still_on_first, 7);
  EXPECT_GT(min_uv_area(m, uv), 0.0);
  EXPECT_NEAR(uv_area(m, uv), 1.0, 1e-12);
  EXPECT_EQ(describe_sheet_problem(analyze_sheet(m.F, m.V.rows()), 1, "twice cut grid"), "");
}

// ---------------------------------------------------------------- collapse_short_edges, smooth_sheet

TEST(CollapseShortEdges, OneShortEdgeOnAGrid) {
  const int n = 6;
  const double h = 1.0 / n;
  auto id = [&](int i, int j) { return i + (n + 1) * j; };
  mesh::TriMesh base = param_test::square_tris(n);
  const int P = id(2, 2), Q = id(3, 2);
  base.V(P, 0) += 0.45 * h;  // edge P-Q is 0.55 h long, every other edge at least h
  const Eigen::MatrixXd uv0 = base.V.leftCols(2);
  std::vector<char> none(static_cast<std::size_t>(base.V.rows()), 0);

  auto uses = [](const mesh::TriMesh& m, int v) { return (m.F.array() == v).any(); };
  {
    mesh::TriMesh m = base;
    Eigen::MatrixXd uv = uv0;
    EXPECT_EQ(collapse_short_edges(m, uv, none, 0.6 * h), 1);
    EXPECT_EQ(m.F.rows(), base.F.rows() - 2);  // the two triangles of the edge
    EXPECT_NE(uses(m, P), uses(m, Q));         // one end is gone
    EXPECT_GT(min_uv_area(m, uv), 0.0);
    EXPECT_NEAR(uv_area(m, uv), 1.0, 1e-12);    // still a triangulation of the square
    EXPECT_EQ(describe_sheet_problem(analyze_sheet(m.F, m.V.rows()), 1, "collapsed grid"), "");
    EXPECT_EQ(m.V, base.V);  // vertices are not moved, only re-used
  }
  {  // A pinned end is never the one that goes.
    mesh::TriMesh m = base;
    Eigen::MatrixXd uv = uv0;
    std::vector<char> pin = none;
    pin[static_cast<std::size_t>(Q)] = 1;
    EXPECT_EQ(collapse_short_edges(m, uv, pin, 0.6 * h), 1);
    EXPECT_TRUE(uses(m, Q));
    EXPECT_FALSE(uses(m, P));
    EXPECT_GT(min_uv_area(m, uv), 0.0);
    pin = none;
    pin[static_cast<std::size_t>(P)] = 1;
    m = base;
    uv = uv0;
    EXPECT_EQ(collapse_short_edges(m, uv, pin, 0.6 * h), 1);
    EXPECT_TRUE(uses(m, P));
    EXPECT_FALSE(uses(m, Q));
  }
  {  // Both ends pinned, or the threshold below the edge: nothing.
    mesh::TriMesh m = base;
    Eigen::MatrixXd uv = uv0;
    std::vector<char> pin = none;
    pin[static_cast<std::size_t>(P)] = pin[static_cast<std::size_t>(Q)] = 1;
    EXPECT_EQ(collapse_short_edges(m, uv, pin, 0.6 * h), 0);
    EXPECT_EQ(m.F, base.F);
    EXPECT_EQ(collapse_short_edges(m, uv, none, 0.5 * h), 0);
    EXPECT_EQ(m.F, base.F);
  }
}

// A 6 x 6 grid with two neighbouring vertices P and Q pinned and P's (u, v)
// moved by `uv_shift` from Q's; the threshold in the tests is 0.1 h.
struct PinnedPair {
  static constexpr int n = 6;
  static constexpr double h = 1.0 / n;
  mesh::TriMesh m = param_test::square_tris(n);
  const int P = 2 + (n + 1) * 2, Q = 3 + (n + 1) * 2;
  Eigen::MatrixXd uv = m.V.leftCols(2);
  std::vector<char> pin = std::vector<char>(static_cast<std::size_t>(m.V.rows()), 0);
  explicit PinnedPair(const Eigen::RowVector2d& uv_shift) {
    uv.row(P) = uv.row(Q) + uv_shift;
    pin[static_cast<std::size_t>(P)] = pin[static_cast<std::size_t>(Q)] = 1;
  }
};

// Two pinned vertices at one (u, v) (cut points that a line put at one place
// where the map is nearly degenerate), 0.3 h apart in 3D with the threshold
// below that: their edge still goes, else its triangles have no (u, v) area.
TEST(CollapseShortEdges, AnEdgeOfNoLengthInUVGoesEvenBetweenPins) {
  PinnedPair g(Eigen::RowVector2d::Zero());          // P's (u, v) on Q's, P's 3D where it was
  g.m.V(g.P, 0) = g.m.V(g.Q, 0) - 0.3 * PinnedPair::h;  // and 0.3 h from Q in 3D
  ASSERT_EQ(min_uv_area(g.m, g.uv), 0.0);
  EXPECT_EQ(collapse_short_edges(g.m, g.uv, g.pin, 0.1 * PinnedPair::h), 1);
  EXPECT_GT(min_uv_area(g.m, g.uv), 0.0);
  EXPECT_EQ(describe_sheet_problem(analyze_sheet(g.m.F, g.m.V.rows()), 1, "collapsed grid"), "");
}

// Two pinned vertices a hundredth of h apart in (u, v) but in the wrong
// order (cut points a line put past each other where the map is nearly
// degenerate), their 3D distance h, above the threshold: the two triangles
// of their edge are turned over, and the edge goes.
TEST(CollapseShortEdges, TheShortestEdgeOfATriangleTurnedOverGoesEvenBetweenPins) {
  PinnedPair g(Eigen::RowVector2d(0.01 * PinnedPair::h, 0.0));  // P's (u, v) just past Q's
  ASSERT_LT(min_uv_area(g.m, g.uv), 0.0);
  EXPECT_EQ(collapse_short_edges(g.m, g.uv, g.pin, 0.1 * PinnedPair::h), 1);
  EXPECT_GT(min_uv_area(g.m, g.uv), 0.0);
  EXPECT_EQ(describe_sheet_problem(analyze_sheet(g.m.F, g.m.V.rows()), 1, "collapsed grid"), "");
}

// Three vertices at one (u, v), 3D apart (cut points where two lines cross
// and the map squeezes to a point, as between the genus-4 statuette's
// stacked holes), joined by triangles of no area: each of those is next to
// another one, so no single move was taken before. All three become one.
TEST(CollapseShortEdges, ThreeVerticesAtOnePlaceBecomeOne) {
  mesh::TriMesh m;
  m.V.resize(7, 3);
  m.V << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.4, 0.0, 0.6, 0.5, 0.1, 0.5, 0.6, -0.1;  // A B C D, P Q R
  Eigen::MatrixXd uv = m.V.leftCols(2);
  for (int v = 4; v < 7; ++v) uv.row(v) << 0.5, 0.5;
  const int A = 0, B = 1, C = 2, D = 3, P = 4, Q = 5, R = 6;
  m.F.resize(8, 3);
  m.F << A, B, P, B, C, Q, C, D, R, D, A, R,  // the fan about the centre
      B, Q, P, C, R, Q, A, P, R, P, Q, R;     // no area
  ASSERT_EQ(describe_sheet_problem(analyze_sheet(m.F, m.V.rows()), 1, "the fan"), "");
  const std::vector<char> pinned(7, 1);
  EXPECT_EQ(collapse_short_edges(m, uv, pinned, 1e-3), 2);
  EXPECT_EQ(m.F.rows(), 4);
  EXPECT_GT(min_uv_area(m, uv), 0.0);
  EXPECT_NEAR(uv_area(m, uv), 1.0, 1e-15);
  EXPECT_EQ(describe_sheet_problem(analyze_sheet(m.F, m.V.rows()), 1, "collapsed fan"), "");
}

TEST(SmoothSheet, FlattensBumpsKeepsFixedAndPlanar) {
  mesh::TriMesh flat = param_test::square_tris(8, 0.2, 4);
  std::vector<char> fixed(static_cast<std::size_t>(flat.V.rows()), 0);
  for (Eigen::Index v = 0; v < flat.V.rows(); ++v)
    fixed[static_cast<std::size_t>(v)] = flat.V(v, 0) == 0.0 || flat.V(v, 0) == 1.0 || flat.V(v, 1) == 0.0 || flat.V(v, 1) == 1.0;
  // A planar sheet does not move at all.
  mesh::TriMesh m = flat;
  smooth_sheet(m, fixed, 10);
  EXPECT_EQ(m.V, flat.V);

  // Bumps on the interior vertices: smoothed out along the normals.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-0.02, 0.02);
  mesh::TriMesh bumpy = flat;
  for (Eigen::Index v = 0; v < bumpy.V.rows(); ++v)
    if (!fixed[static_cast<std::size_t>(v)]) bumpy.V(v, 2) = U(rng);
  m = bumpy;
  smooth_sheet(m, fixed, 10);
  double before = 0.0, after = 0.0, drift = 0.0, moved_z = 0.0;
  for (Eigen::Index v = 0; v < m.V.rows(); ++v) {
    if (fixed[static_cast<std::size_t>(v)]) {
      EXPECT_EQ((m.V.row(v) - bumpy.V.row(v)).norm(), 0.0) << "fixed vertex " << v;
      continue;
    }
    before = std::max(before, std::abs(bumpy.V(v, 2)));
    after = std::max(after, std::abs(m.V(v, 2)));
    drift = std::max(drift, (m.V.row(v).leftCols(2) - bumpy.V.row(v).leftCols(2)).norm());
    moved_z = std::max(moved_z, std::abs(m.V(v, 2) - bumpy.V(v, 2)));
  }
  EXPECT_LT(after, 0.5 * before);
  EXPECT_GT(moved_z, 0.0);
  EXPECT_LT(drift, 0.1 * moved_z);  // moves are (nearly) normal to the nearly flat sheet
}

// A planar grid does not intersect itself, nor does it with a bump; with one
// interior vertex dragged across the sheet in its plane (its triangles then
// overlap others) it does.
TEST(SheetSelfIntersects, PlanarGridAndFoldedGrids) {
  const mesh::TriMesh flat = param_test::square_tris(6);
  EXPECT_FALSE(sheet_self_intersects(flat, "flat"));
  const Eigen::Index centre = 3 + 7 * 3;
  ASSERT_EQ(flat.V.row(centre), Eigen::RowVector3d(0.5, 0.5, 0.0));
  mesh::TriMesh dragged = flat;
  dragged.V.row(centre) << 0.9, 0.1, 0.0;
  EXPECT_TRUE(sheet_self_intersects(dragged, "dragged"));
  mesh::TriMesh lifted = flat;
  lifted.V.row(centre) << 0.5, 0.5, 0.3;  // a bump: still no crossing
  EXPECT_FALSE(sheet_self_intersects(lifted, "lifted"));
}

// A sheet CGAL cannot hold (one triangle flipped against its neighbours) is
// not reported as free of intersections: the question is refused, by name.
TEST(SheetSelfIntersects, UndecidedIsAnError) {
  mesh::TriMesh flipped = param_test::square_tris(6);
  std::swap(flipped.F(7, 1), flipped.F(7, 2));
  try {
    sheet_self_intersects(flipped, "flipped sheet");
    FAIL() << "no error for a sheet that is not an oriented 2-manifold";
  } catch (const igaprep::Error& e) {
    EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput);
    EXPECT_NE(std::string(e.what()).find("flipped sheet: cannot tell whether it intersects itself"), std::string::npos)
        << e.what();
  }
}

// ---------------------------------------------------------------- narrowest_band, inset_base_surface

TEST(NarrowestBand, WidthHeightAndGaps) {
  RectilinearDomain D;
  D.width = 4.0;
  D.height = 3.0;
  EXPECT_EQ(narrowest_band(D), 3.0);
  D.holes = {Eigen::Vector4d(1.5, 1.0, 2.5, 2.0)};
  EXPECT_EQ(narrowest_band(D), 1.0);
  D.holes = {Eigen::Vector4d(0.5, 1.0, 1.5, 2.2), Eigen::Vector4d(1.8, 0.9, 3.6, 2.0)};
  EXPECT_NEAR(narrowest_band(D), 0.3, 1e-15);  // the gap between the holes (u: 1.8 - 1.5)
}

struct InsetCase {
  double W, H, h;
  std::vector<Eigen::Vector4d> holes;
  double m0;
};

void check_inset(const InsetCase& k) {
  const mesh::TriMesh sheet = grid_sheet(k.W, k.H, k.h, k.holes);
  Polycube2D pc;
  pc.domain.width = k.W;
  pc.domain.height = k.H;
  pc.domain.holes = k.holes;
  for (std::size_t i = 0; i < k.holes.size(); ++i) pc.domain.hole_loop.push_back(static_cast<int>(i) + 1);
  pc.uv = sheet.V.leftCols(2);
  const double d = 0.5 * k.m0 * narrowest_band(pc.domain);

  const InsetBase base = inset_base_surface(sheet, pc, k.m0, 20);
  EXPECT_DOUBLE_EQ(base.inset, d);
  EXPECT_EQ(base.smoothing, 20);  // all rounds: M does not intersect itself
  ASSERT_EQ(base.uv.rows(), base.mesh.V.rows());
  ASSERT_GT(base.uv.rows(), 0);
  // Each cut line is shifted from its nominal place by at most 0.2 mean
  // (u, v) edges (away from the vertices; the grid's mean edge 1.1 h), and
  // (u, v) starts at the left/bottom lines: planar, so 3D = (u, v) + that
  // offset for every vertex (no smoothing moves a planar sheet).
  const double shift = 0.25 * k.h;
  const Eigen::RowVector2d offset = base.mesh.V.row(0).leftCols(2) - base.uv.row(0);
  EXPECT_LE(std::abs(offset.x() - d), shift);
  EXPECT_LE(std::abs(offset.y() - d), shift);
  const RectilinearDomain& D = base.domain;
  EXPECT_LE(std::abs(D.width - (k.W - 2 * d)), 2 * shift);
  EXPECT_LE(std::abs(D.height - (k.H - 2 * d)), 2 * shift);
  ASSERT_EQ(D.holes.size(), k.holes.size());
  double expected_area = D.width * D.height;
  for (std::size_t i = 0; i < k.holes.size(); ++i) {
    const Eigen::Vector4d nominal = k.holes[i] + Eigen::Vector4d(-d, -d, d, d) -
                                    Eigen::Vector4d(offset.x(), offset.y(), offset.x(), offset.y());
    EXPECT_LE((D.holes[i] - nominal).cwiseAbs().maxCoeff(), shift) << "hole " << i;
    expected_area -= (D.holes[i](2) - D.holes[i](0)) * (D.holes[i](3) - D.holes[i](1));
  }

  // (u, v) inside the inset domain.
  for (Eigen::Index v = 0; v < base.uv.rows(); ++v) {
    const Eigen::Vector2d q = base.uv.row(v);
    EXPECT_TRUE(q.x() >= 0.0 && q.x() <= D.width && q.y() >= 0.0 && q.y() <= D.height) << "vertex " << v;
    for (const auto& h : D.holes) EXPECT_FALSE(q.x() > h(0) && q.x() < h(2) && q.y() > h(1) && q.y() < h(3));
    EXPECT_NEAR((base.mesh.V.row(v).leftCols(2) - (base.uv.row(v) + offset)).norm(), 0.0, 1e-12) << "vertex " << v;
    EXPECT_EQ(base.mesh.V(v, 2), 0.0);
  }
  EXPECT_GT(min_uv_area(base.mesh, base.uv), 0.0);
  // Boundary vertices lie exactly on the inset lines.
  std::vector<double> us{0.0, D.width}, vs{0.0, D.height};
  for (const auto& h : D.holes) us.push_back(h(0)), us.push_back(h(2)), vs.push_back(h(1)), vs.push_back(h(3));
  const std::vector<int> bnd = boundary_vertices(base.mesh);
  EXPECT_GT(bnd.size(), 20u);
  for (int v : bnd) {
    bool on = false;
    for (double c : us) on |= base.uv(v, 0) == c && base.uv(v, 1) >= 0.0 && base.uv(v, 1) <= D.height;
    for (double c : vs) on |= base.uv(v, 1) == c && base.uv(v, 0) >= 0.0 && base.uv(v, 0) <= D.width;
    EXPECT_TRUE(on) << "boundary vertex " << v << " at (" << base.uv(v, 0) << ", " << base.uv(v, 1) << ")";
  }
  EXPECT_NEAR(uv_area(base.mesh, base.uv), expected_area, 1e-9);
  EXPECT_NEAR(area_3d(base.mesh), expected_area, 1e-9);
  const SheetTopology topo = analyze_sheet(base.mesh.F, base.mesh.V.rows());
  EXPECT_EQ(topo.boundary_loops.size(), k.holes.size() + 1);
  EXPECT_EQ(topo.components, 1);
}

TEST(InsetBaseSurface, SquareSheetNoHole) {
  // band = min(2, 1.5) = 1.5, d = 0.5 * 0.5 * 1.5 = 0.375 (1.5 cells of 0.25).
  check_inset({2.0, 1.5, 0.25, {}, 0.5});
  // d = 0.5: the nominal lines run through grid vertices and are moved off them.
  check_inset({2.0, 2.0, 0.25, {}, 0.5});
}

TEST(InsetBaseSurface, SquareSheetOneHole) {
  // band = 1 (hole to the top and bottom), d = 0.5 * 0.25 = 0.125.
  check_inset({4.0, 3.0, 0.25, {Eigen::Vector4d(1.5, 1.0, 2.5, 2.0)}, 0.25});
}

TEST(InsetBaseSurface, AlignedHolesStayAligned) {
  // Two holes with common bottom and top lines: band = 0.5 (hole 1 to the
  // left side), d = 0.125. The grown holes still share those lines exactly,
  // so the layout has 5 x 3 cells - 2 holes = 13 rectangles, and 16 outer +
  // 8 hole crests.
  const std::vector<Eigen::Vector4d> holes{Eigen::Vector4d(0.5, 1.0, 1.5, 2.0), Eigen::Vector4d(2.5, 1.0, 3.5, 2.0)};
  check_inset({4.0, 3.0, 0.25, holes, 0.5});
  const mesh::TriMesh sheet = grid_sheet(4.0, 3.0, 0.25, holes);
  Polycube2D pc;
  pc.domain.width = 4.0;
  pc.domain.height = 3.0;
  pc.domain.holes = holes;
  pc.domain.hole_loop = {1, 2};
  pc.uv = sheet.V.leftCols(2);
  const InsetBase base = inset_base_surface(sheet, pc, 0.5, 20);
  ASSERT_EQ(base.domain.holes.size(), 2u);
  EXPECT_EQ(base.domain.holes[0](1), base.domain.holes[1](1));
  EXPECT_EQ(base.domain.holes[0](3), base.domain.holes[1](3));
  const BaseLayout L = base_layout(base);
  EXPECT_EQ(L.rectangles.size(), 13u);
  EXPECT_EQ(L.crests.size(), 24u);
  EXPECT_EQ(L.domain_edges.size(), 12u);
}

TEST(InsetBaseSurface, CurvedSheetStaysNearItsSurface) {
  // A wavy sheet z = A sin(3x) over the same (u, v) = (x, y). Without
  // smoothing, every vertex is a grid vertex (on the surface) or a cut
  // vertex interpolated along an edge: within the chord error A 9 h^2 / 8.
  // Taubin smoothing (20 rounds) then flattens the wave a little (it is
  // meant to remove tet-scale waves): measured 0.0076 = 5 % of A here.
  const double A = 0.15, h = 0.125, chord = A * 9.0 * h * h / 8.0;
  mesh::TriMesh sheet = grid_sheet(2.0, 1.5, h);
  for (Eigen::Index v = 0; v < sheet.V.rows(); ++v) sheet.V(v, 2) = A * std::sin(3.0 * sheet.V(v, 0));
  Polycube2D pc;
  pc.domain.width = 2.0;
  pc.domain.height = 1.5;
  pc.uv = sheet.V.leftCols(2);
  for (int smoothing : {0, 20}) {
    const InsetBase base = inset_base_surface(sheet, pc, 0.5, smoothing);
    const RectilinearDomain& D = base.domain;
    EXPECT_GT(min_uv_area(base.mesh, base.uv), 0.0);
    EXPECT_NEAR(uv_area(base.mesh, base.uv), D.width * D.height, 1e-12);
    double worst = 0.0;
    int corners = 0;
    for (Eigen::Index v = 0; v < base.mesh.V.rows(); ++v) {
      const Eigen::RowVector3d x = base.mesh.V.row(v);
      const double off = std::abs(x.z() - A * std::sin(3.0 * x.x()));
      worst = std::max(worst, off);
      if ((base.uv(v, 0) == 0.0 || base.uv(v, 0) == D.width) && (base.uv(v, 1) == 0.0 || base.uv(v, 1) == D.height)) {
        ++corners;
        EXPECT_LT(off, chord) << "corner vertex " << v << " (never smoothed)";
      }
    }
    EXPECT_EQ(corners, 4);
    EXPECT_LT(worst, smoothing == 0 ? chord : 0.1 * A) << "smoothing " << smoothing;
    const SheetTopology topo = analyze_sheet(base.mesh.F, base.mesh.V.rows());
    EXPECT_EQ(describe_sheet_problem(topo, 1, "inset wavy sheet"), "");
  }
}

TEST(InsetBaseSurface, BadM0) {
  const mesh::TriMesh sheet = grid_sheet(1.0, 1.0, 0.25);
  Polycube2D pc;
  pc.domain.width = pc.domain.height = 1.0;
  pc.uv = sheet.V.leftCols(2);
  for (double m0 : {0.0, 1.0, -0.2}) {
    try {
      inset_base_surface(sheet, pc, m0, 20);
      ADD_FAILURE() << "m0 = " << m0 << " accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    }
  }
}

// ---------------------------------------------------------------- SheetSampler

TEST(SheetSampler, PlanarSheetIsExact) {
  // X(u, v) = o + u a + v b: a skewed, stretched plane.
  const Eigen::Vector3d o(0.3, -1.0, 2.0), a(1.5, 0.2, -0.4), b(0.3, 0.8, 0.9);
  mesh::TriMesh m = param_test::square_tris(6, 0.2, 3);
  const Eigen::MatrixXd uv = m.V.leftCols(2);
  for (Eigen::Index v = 0; v < m.V.rows(); ++v) m.V.row(v) = (o + uv(v, 0) * a + uv(v, 1) * b).transpose();
  const SheetSampler sampler(m, uv, 3);
  const Eigen::Vector3d n = a.cross(b).normalized();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int i = 0; i < 100; ++i) {
    const Eigen::Vector2d q(U(rng), U(rng));
    const SheetPoint p = sampler.at(q);
    EXPECT_NEAR((p.position - (o + q.x() * a + q.y() * b)).norm(), 0.0, 1e-12);
    EXPECT_NEAR((p.normal - n).norm(), 0.0, 1e-12);
    EXPECT_NEAR((p.du - a).norm(), 0.0, 1e-12);
    EXPECT_NEAR((p.dv - b).norm(), 0.0, 1e-12);
    ASSERT_GE(p.triangle, 0);
    ASSERT_LT(p.triangle, m.F.rows());
    EXPECT_NEAR(p.bary.sum(), 1.0, 1e-14);
    EXPECT_GE(p.bary.minCoeff(), -1e-12);
    Eigen::Vector2d back = Eigen::Vector2d::Zero();
    for (int k = 0; k < 3; ++k) back += p.bary(k) * uv.row(m.F(p.triangle, k)).transpose();
    EXPECT_NEAR((back - q).norm(), 0.0, 1e-12);
  }
  // Outside the (u, v) image: the nearest point of it.
  const SheetPoint out = sampler.at(Eigen::Vector2d(-0.1, 0.4));
  EXPECT_NEAR((out.position - (o + 0.4 * b)).norm(), 0.0, 1e-12);
  const SheetPoint corner = sampler.at(Eigen::Vector2d(1.2, 1.3));
  EXPECT_NEAR((corner.position - (o + a + b)).norm(), 0.0, 1e-12);
}

TEST(SheetSampler, RefusesFoldedOrMismatchedUv) {
  mesh::TriMesh m = param_test::square_tris(3);
  Eigen::MatrixXd uv = m.V.leftCols(2);
  Eigen::MatrixXd flipped = uv;
  flipped.col(0) *= -1.0;  // every triangle reversed
  EXPECT_THROW(SheetSampler(m, flipped), Error);
  const Eigen::MatrixXd short_uv = uv.topRows(uv.rows() - 1);
  EXPECT_THROW(SheetSampler(m, short_uv), Error);
}

// ---------------------------------------------------------------- FieldProbe

struct LinearField {
  mesh::TetMesh mesh;
  TetTopology topo;
  Eigen::VectorXd u;
  Eigen::MatrixXd grad;
  Eigen::Vector3d a{0.7, -0.4, 1.1};
  double b = 0.25;
  LinearField() : LinearField(param_test::box_tets(5, 5, 5, 0.15, 3)) {}
  explicit LinearField(mesh::TetMesh m) : mesh(std::move(m)) {
    topo = build_tet_topology(mesh.T, mesh.V.rows());
    u = mesh.V * a + Eigen::VectorXd::Constant(mesh.V.rows(), b);
    grad = vertex_gradients(mesh.V, mesh.T, u);
  }
  double exact(const Eigen::Vector3d& p) const { return a.dot(p) + b; }
};

TEST(FieldProbe, LinearFieldInAJitteredBox) {
  const LinearField f;
  const FieldProbe probe(f.mesh.V, f.mesh.T, f.topo, f.u, f.grad);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(0.01, 0.99);
  int hint = -1;
  for (int i = 0; i < 200; ++i) {
    const Eigen::Vector3d p(U(rng), U(rng), U(rng));
    Eigen::Vector4d bary;
    const int c = probe.locate(p, i % 2 ? &hint : nullptr, &bary);
    ASSERT_GE(c, 0);
    Eigen::Vector3d back = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) back += bary(k) * f.mesh.V.row(f.mesh.T(c, k)).transpose();
    EXPECT_NEAR((back - p).norm(), 0.0, 1e-12);
    EXPECT_NEAR(probe.value(p, &hint), f.exact(p), 1e-12);
    EXPECT_NEAR(probe.smooth_value(p, &hint), f.exact(p), 1e-12);
    Eigen::Vector3d g;
    ASSERT_TRUE(probe.gradient(p, &hint, &g));
    EXPECT_NEAR((g - f.a).norm(), 0.0, 1e-10);
  }
  // Outside the box.
  const Eigen::Vector3d far(1.5, 0.5, 0.5);
  EXPECT_TRUE(std::isnan(probe.value(far)));
  EXPECT_TRUE(std::isnan(probe.smooth_value(far)));
  Eigen::Vector3d g;
  EXPECT_FALSE(probe.gradient(far, nullptr, &g));
  EXPECT_EQ(probe.locate(far, nullptr, nullptr), -1);
}

// A fresh query just outside H (within the scan's tolerance) finds the tet
// the scan of every tet finds, without that scan; one farther out none.
TEST(FieldProbe, AFreshQueryJustOutsideFindsTheScansTet) {
  const LinearField f;
  const FieldProbe probe(f.mesh.V, f.mesh.T, f.topo, f.u, f.grad);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(0.02, 0.98);
  for (int i = 0; i < 50; ++i) {
    const Eigen::Vector3d near(1.0 + 1e-11, U(rng), U(rng)), beyond(1.0 + 1e-6, U(rng), U(rng));
    Eigen::Vector4d b_probe, b_scan;
    const int c = probe.locate(near, nullptr, &b_probe);
    ASSERT_GE(c, 0);
    EXPECT_EQ(c, locate_in_tets(f.mesh.V, f.mesh.T, f.topo, near, -1, &b_scan, true));
    EXPECT_EQ(b_probe, b_scan);
    EXPECT_NEAR(probe.value(near), f.exact(near), 1e-9);
    EXPECT_EQ(probe.locate(beyond, nullptr, nullptr), -1);
    EXPECT_EQ(locate_in_tets(f.mesh.V, f.mesh.T, f.topo, beyond, -1, nullptr, true), -1);
  }
}

TEST(FieldProbe, RayToLevelLandsOnThePlane) {
  const LinearField f;
  const FieldProbe probe(f.mesh.V, f.mesh.T, f.topo, f.u, f.grad);
  const Eigen::Vector3d start(0.8, 0.3, 0.85);
  const double u0 = f.exact(start);
  for (const Eigen::Vector3d& dir0 : {Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(-0.3, 0.2, -1.0),
                                      Eigen::Vector3d(-f.a)}) {
    const Eigen::Vector3d dir = dir0.normalized();
    const double rate = f.a.dot(dir);  // du/dt along the ray, < 0
    ASSERT_LT(rate, 0.0);
    for (double level : {u0 - 0.05, u0 - 0.3}) {
      int hint = -1;
      const Eigen::Vector3d x = probe.ray_to_level(start, dir, level, 0.01, 2.0, &hint);
      EXPECT_NEAR(f.exact(x), level, 1e-10);
      EXPECT_NEAR(((x - start) - (x - start).dot(dir) * dir).norm(), 0.0, 1e-12);  // on the ray
      EXPECT_NEAR((x - start).dot(dir), (level - u0) / rate, 1e-10);
      EXPECT_GE(hint, 0);
    }
  }
  // Failures: start below the level, the ray leaving the box, a level too far.
  auto kind = [&](const Eigen::Vector3d& dir, double level, double max_length) {
    try {
      probe.ray_to_level(start, dir.normalized(), level, 0.01, max_length);
    } catch (const Error& e) {
      return e.kind();
    }
    return ErrorKind::Internal;  // no throw
  };
  EXPECT_EQ(kind(Eigen::Vector3d(-1, 0, 0), u0 + 0.1, 2.0), ErrorKind::CheckFailed);
  EXPECT_EQ(kind(Eigen::Vector3d(1, 0, 0), u0 - 0.1, 2.0), ErrorKind::CheckFailed);   // u rises: leaves the box
  EXPECT_EQ(kind(Eigen::Vector3d(-1, 0, 0), u0 - 0.5, 0.1), ErrorKind::CheckFailed);  // not within 0.1
}

TEST(FieldProbe, SphericalShellRayIntoTheHole) {
  // A non-convex mesh: value/gradient exact for a linear field; a ray
  // through the inner cavity fails with check_failed.
  const LinearField f(param_test::spherical_shell(2, 3, 1.0, 2.0).mesh);
  const FieldProbe probe(f.mesh.V, f.mesh.T, f.topo, f.u, f.grad);
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(1.5, 0.0, 0.0), Eigen::Vector3d(0.0, -1.2, 0.9),
                                   Eigen::Vector3d(-1.0, 0.8, -0.9)}) {
    EXPECT_NEAR(probe.value(p), f.exact(p), 1e-12);
    EXPECT_NEAR(probe.smooth_value(p), f.exact(p), 1e-12);
    Eigen::Vector3d g;
    ASSERT_TRUE(probe.gradient(p, nullptr, &g));
    EXPECT_NEAR((g - f.a).norm(), 0.0, 1e-10);
  }
  EXPECT_TRUE(std::isnan(probe.value(Eigen::Vector3d(0.1, 0.2, 0.0))));  // in the cavity
  // From (1.9, 0, 0) down -x: u falls by 0.7 per unit; level u0 - 0.2 is reached in the shell,
  // u0 - 1.5 only beyond the cavity.
  const Eigen::Vector3d start(1.9, 0.0, 0.0);
  const double u0 = f.exact(start);
  const Eigen::Vector3d x = probe.ray_to_level(start, Eigen::Vector3d(-1, 0, 0), u0 - 0.2, 0.02, 5.0);
  EXPECT_NEAR(f.exact(x), u0 - 0.2, 1e-10);
  EXPECT_THROW(probe.ray_to_level(start, Eigen::Vector3d(-1, 0, 0), u0 - 1.5, 0.02, 5.0), Error);
}

TEST(FieldProbe, RidgeTetsUseTheirOwnGradient) {
  // u = x^2 on a box: vertex gradients average neighbouring cells; next to
  // the ridge (u >= 0.5) the tet's own gradient is used.
  const mesh::TetMesh m = param_test::box_tets(4, 4, 4, 0.1, 9);
  const TetTopology topo = build_tet_topology(m.T, m.V.rows());
  const Eigen::VectorXd u = m.V.col(0).array().square().matrix();
  const Eigen::MatrixXd vg = vertex_gradients(m.V, m.T, u), cg = cell_gradients(m.V, m.T, u);
  FieldProbe probe(m.V, m.T, topo, u, vg);
  const double ridge = 0.5;
  int checked_ridge = 0, checked_plain = 0;
  for (Eigen::Index c = 0; c < m.T.rows(); ++c) {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    bool on_ridge = false;
    for (int k = 0; k < 4; ++k) centre += m.V.row(m.T(c, k)).transpose() / 4.0, on_ridge |= u(m.T(c, k)) >= ridge;
    Eigen::Vector3d before, after;
    int hint = static_cast<int>(c);
    probe.set_ridge(std::numeric_limits<double>::infinity());
    ASSERT_TRUE(probe.gradient(centre, &hint, &before));
    ASSERT_EQ(hint, static_cast<int>(c));
    Eigen::Vector3d blend = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) blend += 0.25 * vg.row(m.T(c, k)).transpose();
    EXPECT_NEAR((before - blend).norm(), 0.0, 1e-12);
    probe.set_ridge(ridge);
    ASSERT_TRUE(probe.gradient(centre, &hint, &after));
    if (on_ridge) {
      EXPECT_NEAR((after - cg.row(c).transpose()).norm(), 0.0, 1e-10) << "tet " << c;
      ++checked_ridge;
    } else {
      EXPECT_EQ((after - before).norm(), 0.0);
      ++checked_plain;
    }
  }
  EXPECT_GT(checked_ridge, 50);
  EXPECT_GT(checked_plain, 50);
}

// ---------------------------------------------------------------- trace_column

TEST(TraceColumn, LinearFieldGivesAStraightColumn) {
  const LinearField f;
  const FieldProbe probe(f.mesh.V, f.mesh.T, f.topo, f.u, f.grad);
  const Eigen::Vector3d start(0.62, 0.41, 0.77);
  const Eigen::Vector3d down = -f.a.normalized();
  int hint = -1;
  const StreamlineColumn col = trace_column(probe, start, 0.01, &hint);
  EXPECT_GE(hint, 0);
  const Eigen::Index k = col.path.rows();
  ASSERT_GT(k, 20);
  ASSERT_EQ(col.w.size(), k);
  ASSERT_EQ(col.arc.size(), k);
  EXPECT_EQ((col.path.row(0).transpose() - start).norm(), 0.0);
  for (Eigen::Index j = 0; j < k; ++j) {
    const Eigen::Vector3d p = col.path.row(j).transpose();
    EXPECT_NEAR(((p - start) - (p - start).dot(down) * down).norm(), 0.0, 1e-9) << "point " << j;
    EXPECT_NEAR(col.w(j), f.exact(p), 1e-12);
    EXPECT_NEAR(col.arc(j), (p - start).norm(), 1e-9);
    if (j > 0) {
      EXPECT_GT(col.arc(j), col.arc(j - 1));
      EXPECT_LT(col.w(j), col.w(j - 1));
    }
  }
  // The end point is on the box's boundary (T1): the line from start along
  // `down` leaves the unit cube at the first coordinate reaching 0 or 1.
  double t_exit = std::numeric_limits<double>::infinity();
  for (int d = 0; d < 3; ++d) {
    if (down(d) < 0) t_exit = std::min(t_exit, -start(d) / down(d));
    if (down(d) > 0) t_exit = std::min(t_exit, (1.0 - start(d)) / down(d));
  }
  EXPECT_NEAR(col.arc(k - 1), t_exit, 1e-9);
  EXPECT_NEAR((col.path.row(k - 1).transpose() - (start + t_exit * down)).norm(), 0.0, 1e-9);

  // Levels: at_level(l) lies on u = l; arc monotone in the level.
  const double top = col.w(0), bottom = col.w(k - 1);
  double last_arc = -1.0;
  for (int i = 0; i <= 10; ++i) {
    const double level = top - (top - bottom) * i / 10.0;
    const double s = col.arc_at_level(level);
    EXPECT_GE(s, last_arc);
    last_arc = s;
    EXPECT_NEAR(f.exact(col.at_level(level)), level, 1e-9) << "level " << level;
    EXPECT_NEAR(s, (top - level) / f.a.norm(), 1e-9);
  }
  EXPECT_EQ(col.arc_at_level(top + 1.0), 0.0);
  EXPECT_EQ(col.arc_at_level(bottom - 1.0), col.arc(k - 1));
  EXPECT_EQ((col.at_arc(-1.0) - start).norm(), 0.0);
  EXPECT_EQ((col.at_arc(1e9) - col.path.row(k - 1).transpose()).norm(), 0.0);

  // stop_level: the column ends at the first point at or below it.
  const double stop = top - 0.4 * (top - bottom);
  const StreamlineColumn part = trace_column(probe, start, 0.01, nullptr, stop);
  const Eigen::Index kp = part.path.rows();
  ASSERT_GE(kp, 2);
  EXPECT_LE(part.w(kp - 1), stop);
  EXPECT_GT(part.w(kp - 2), stop);
  EXPECT_LT(kp, k);
}

TEST(TraceColumn, RadialFieldInASphericalShell) {
  // u = |x| on the shell 1 < r < 2: -grad u points to the centre, so the
  // column from a point runs (nearly: P1 vertex gradients) radially in to
  // the inner sphere.
  const param_test::Shell shell = param_test::spherical_shell(3, 4, 1.0, 2.0);
  const mesh::TetMesh& m = shell.mesh;
  const TetTopology topo = build_tet_topology(m.T, m.V.rows());
  const Eigen::VectorXd u = m.V.rowwise().norm();
  const Eigen::MatrixXd grad = vertex_gradients(m.V, m.T, u);
  const FieldProbe probe(m.V, m.T, topo, u, grad);
  for (const Eigen::Vector3d& start : {Eigen::Vector3d(1.8, 0.1, 0.2), Eigen::Vector3d(-0.5, 1.1, -1.0)}) {
    const StreamlineColumn col = trace_column(probe, start, 0.01);
    const Eigen::Index k = col.path.rows();
    ASSERT_GT(k, 10);
    const Eigen::Vector3d dir = start.normalized();
    double off_axis = 0.0;
    for (Eigen::Index j = 0; j < k; ++j) {
      const Eigen::Vector3d p = col.path.row(j).transpose();
      off_axis = std::max(off_axis, (p - p.dot(dir) * dir).norm());
      if (j > 0) EXPECT_GT(col.arc(j), col.arc(j - 1));
    }
    EXPECT_LT(off_axis, 5e-3);  // measured 2.0e-3 and 1.4e-3
    // It ends on the inner boundary (the polyhedral sphere: r within 1 and its inradius).
    const double r_end = col.path.row(k - 1).norm();
    EXPECT_LE(r_end, 1.0 + 1e-9);
    EXPECT_GT(r_end, 0.98);
    EXPECT_NEAR(col.arc(k - 1), start.norm() - r_end, 1e-4);  // measured 6e-6
    EXPECT_NEAR(col.at_level(1.5).norm(), 1.5, 1e-2);  // P1 |x| is larger than |x|: 1.495
    EXPECT_NEAR(probe.value(col.at_level(1.5)), 1.5, 1e-9);
  }
}

TEST(TraceColumn, Failures) {
  const LinearField f;
  const FieldProbe probe(f.mesh.V, f.mesh.T, f.topo, f.u, f.grad);
  auto kind = [&](const FieldProbe& p, const Eigen::Vector3d& start, double step, int max_steps) {
    try {
      trace_column(p, start, step, nullptr, 0.0, max_steps);
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("streamline from"), std::string::npos) << e.what();
      return e.kind();
    }
    return ErrorKind::Internal;  // no throw
  };
  // The step budget: a shape (an extremum of w) the user can change by the mesh or the cut, exit 1.
  EXPECT_EQ(kind(probe, Eigen::Vector3d(0.5, 0.5, 0.5), 1e-4, 10), ErrorKind::BadInput);
  EXPECT_EQ(kind(probe, Eigen::Vector3d(2.0, 0.5, 0.5), 0.01, 1000), ErrorKind::CheckFailed);  // outside H
  const Eigen::VectorXd flat = Eigen::VectorXd::Constant(f.mesh.V.rows(), 0.3);
  const Eigen::MatrixXd zero = Eigen::MatrixXd::Zero(f.mesh.V.rows(), 3);
  const FieldProbe constant(f.mesh.V, f.mesh.T, f.topo, flat, zero);
  // No gradient where it starts (a flattened extremum): the mesh or the cut, exit 1.
  EXPECT_EQ(kind(constant, Eigen::Vector3d(0.5, 0.5, 0.5), 0.01, 1000), ErrorKind::BadInput);
}

TEST(TraceColumn, CrossesAPlateauOfWInItsLastDirection) {
  // w flattened in a slab (its gradient zero there, as around a flattened
  // interior extremum): the streamline goes straight through and on to T1.
  const LinearField f;
  Eigen::MatrixXd grad = f.grad;
  for (Eigen::Index v = 0; v < grad.rows(); ++v)
    if (f.mesh.V(v, 0) > 0.35 && f.mesh.V(v, 0) < 0.65) grad.row(v).setZero();
  const FieldProbe probe(f.mesh.V, f.mesh.T, f.topo, f.u, grad);
  const Eigen::Vector3d start(0.9, 0.5, 0.9);
  const StreamlineColumn col = trace_column(probe, start, 0.01, nullptr, 0.0, 10000);
  const Eigen::Vector3d end = col.path.bottomRows(1).transpose();
  EXPECT_LT(end.x(), 0.35);  // past the slab
  EXPECT_LT(col.w(col.w.size() - 1), f.exact(start) - 0.3);
  // On the box's boundary: some coordinate at 0 or 1 (to the bisection's tolerance).
  EXPECT_LT(std::min({end.minCoeff(), 1.0 - end.maxCoeff()}), 1e-6);
}

// A discrete w with a minimum inside the solid (a bowl around the box's
// centre): the streamline is caught there, and the error is bad input that
// names the stage, the start and the case keys that change it (issue 16's
// failure class "streamlines that do not reach T1"), not a failed check.
TEST(TraceColumn, AStreamlineCaughtAtAnInteriorMinimumNamesTheKeysThatChangeIt) {
  LinearField f;
  const Eigen::Vector3d centre(0.5, 0.5, 0.5);
  for (Eigen::Index v = 0; v < f.u.size(); ++v) f.u(v) = (f.mesh.V.row(v).transpose() - centre).squaredNorm();
  f.grad = vertex_gradients(f.mesh.V, f.mesh.T, f.u);
  const FieldProbe probe(f.mesh.V, f.mesh.T, f.topo, f.u, f.grad);
  try {
    trace_column(probe, Eigen::Vector3d(0.8, 0.3, 0.7), 0.01, nullptr, 0.0, 2000);
    FAIL() << "the streamline cannot leave the bowl";
  } catch (const igaprep::Error& e) {
    EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput) << e.what();
    const std::string m = e.what();
    EXPECT_NE(m.find("param: the streamline from (0.8 0.3 0.7)"), std::string::npos) << m;
    EXPECT_NE(m.find("finds no exit through T1 within 2000 steps"), std::string::npos) << m;
    EXPECT_NE(m.find("'tetmesh.max_volume'"), std::string::npos) << m;
    EXPECT_NE(m.find("'midsurface.cut'"), std::string::npos) << m;
  }
}

TEST(TraceColumn, TheLevelOfT1IsWhereTheColumnEnds) {
  // w = 0 on a band of vertices before T1, as inside the slivers TetGen
  // leaves against a concave part of T1 (all four vertices on T1): the
  // level 0 is still the column's end on T1, not the band's near side.
  LinearField f;
  for (Eigen::Index v = 0; v < f.u.size(); ++v) f.u(v) = std::max(f.u(v) - 0.5, 0.0);
  f.grad = vertex_gradients(f.mesh.V, f.mesh.T, f.u);
  const FieldProbe probe(f.mesh.V, f.mesh.T, f.topo, f.u, f.grad);
  const StreamlineColumn col = trace_column(probe, Eigen::Vector3d(0.62, 0.41, 0.77), 0.01, nullptr, 0.0, 10000);
  const Eigen::Index k = col.path.rows();
  Eigen::Index first_zero = 0;
  while (first_zero < k && col.w(first_zero) > 0.0) ++first_zero;
  ASSERT_LT(first_zero + 5, k);  // the band is several steps wide
  EXPECT_EQ(col.arc_at_level(0.0), col.arc(k - 1));
  const Eigen::Vector3d end = col.at_level(0.0);
  EXPECT_LT(std::min(end.minCoeff(), 1.0 - end.maxCoeff()), 1e-6);  // on the box's boundary
  EXPECT_LT(col.arc_at_level(0.1), col.arc(first_zero));  // other levels as before
}

// ---------------------------------------------------------------- base_layout

TEST(BaseLayout, OneHoleDomain) {
  InsetBase base;
  base.mesh = grid_sheet(3.0, 2.0, 0.5, {Eigen::Vector4d(1.0, 0.5, 2.0, 1.5)});
  base.uv = base.mesh.V.leftCols(2);
  base.domain.width = 3.0;
  base.domain.height = 2.0;
  base.domain.holes = {Eigen::Vector4d(1.2, 0.6, 2.1, 1.3)};  // off-centre, need not match the mesh
  base.domain.hole_loop = {1};
  const RectilinearDomain& D = base.domain;
  const Eigen::Vector4d h = D.holes[0];

  EXPECT_TRUE(inside_domain(D, Eigen::Vector2d(0.5, 0.5)));
  EXPECT_FALSE(inside_domain(D, Eigen::Vector2d(1.5, 1.0)));  // in the hole
  EXPECT_FALSE(inside_domain(D, Eigen::Vector2d(0.0, 1.0)));  // on the outer side
  EXPECT_FALSE(inside_domain(D, Eigen::Vector2d(1.2, 1.0)));  // on the hole's side
  EXPECT_FALSE(inside_domain(D, Eigen::Vector2d(3.5, 1.0)));

  const BaseLayout L = base_layout(base);
  EXPECT_EQ(L.sheet.F, base.mesh.F);
  EXPECT_EQ(L.uv, base.uv);
  ASSERT_EQ(L.rectangles.size(), 8u);
  double rect_area = 0.0;
  for (const auto& r : L.rectangles) {
    EXPECT_GT(r(2), r(0));
    EXPECT_GT(r(3), r(1));
    rect_area += (r(2) - r(0)) * (r(3) - r(1));
    EXPECT_TRUE(inside_domain(D, Eigen::Vector2d(0.5 * (r(0) + r(2)), 0.5 * (r(1) + r(3)))));
  }
  EXPECT_NEAR(rect_area, 6.0 - (h(2) - h(0)) * (h(3) - h(1)), 1e-12);

  ASSERT_EQ(L.crests.size(), 16u);
  int on_outer = 0, on_hole = 0;
  double outer_length = 0.0, hole_length = 0.0;
  for (const auto& c : L.crests) {
    ASSERT_GE(c.rectangle, 0);
    ASSERT_LT(c.rectangle, 8);
    const Eigen::Vector4d r = L.rectangles[static_cast<std::size_t>(c.rectangle)];
    // The segment is that side of its rectangle, in the rectangle's u or v direction.
    const Eigen::Vector2d d = c.b - c.a;
    const bool horizontal = c.side == 0 || c.side == 2;
    EXPECT_EQ(horizontal ? d.y() : d.x(), 0.0);
    EXPECT_GT(horizontal ? d.x() : d.y(), 0.0);
    switch (c.side) {
      case 0: EXPECT_EQ(c.a.y(), r(1)); EXPECT_EQ(c.a.x(), r(0)); EXPECT_EQ(c.b.x(), r(2)); break;
      case 1: EXPECT_EQ(c.a.x(), r(2)); EXPECT_EQ(c.a.y(), r(1)); EXPECT_EQ(c.b.y(), r(3)); break;
      case 2: EXPECT_EQ(c.a.y(), r(3)); EXPECT_EQ(c.a.x(), r(0)); EXPECT_EQ(c.b.x(), r(2)); break;
      case 3: EXPECT_EQ(c.a.x(), r(0)); EXPECT_EQ(c.a.y(), r(1)); EXPECT_EQ(c.b.y(), r(3)); break;
      default: ADD_FAILURE() << "side " << c.side;
    }
    // On the domain's boundary: the outer rectangle's sides or the hole's.
    const bool outer = (horizontal && (c.a.y() == 0.0 || c.a.y() == D.height)) ||
                       (!horizontal && (c.a.x() == 0.0 || c.a.x() == D.width));
    const bool hole = (horizontal && (c.a.y() == h(1) || c.a.y() == h(3)) && c.a.x() >= h(0) && c.b.x() <= h(2)) ||
                      (!horizontal && (c.a.x() == h(0) || c.a.x() == h(2)) && c.a.y() >= h(1) && c.b.y() <= h(3));
    EXPECT_TRUE(outer || hole) << "crest of rectangle " << c.rectangle << " side " << c.side;
    on_outer += outer, on_hole += hole;
    (outer ? outer_length : hole_length) += d.norm();
  }
  EXPECT_EQ(on_outer, 12);
  EXPECT_EQ(on_hole, 4);
  EXPECT_NEAR(outer_length, 2 * (D.width + D.height), 1e-12);
  EXPECT_NEAR(hole_length, 2 * (h(2) - h(0) + h(3) - h(1)), 1e-12);

  // Domain edges: the outer sides pointing out, the hole's pointing into the hole.
  ASSERT_EQ(L.domain_edges.size(), 8u);
  for (const auto& e : L.domain_edges) {
    const Eigen::Vector2d mid = 0.5 * (e.a + e.b);
    EXPECT_EQ(e.outward.norm(), 1.0);
    EXPECT_EQ(e.outward.dot(e.b - e.a), 0.0);
    EXPECT_FALSE(inside_domain(D, mid + 1e-3 * e.outward));
    EXPECT_TRUE(inside_domain(D, mid - 1e-3 * e.outward));
  }
}

// The layout of a 4 x 3 sheet with the hole [1.5, 2.5] x [1, 2], inset by 0.25.
BaseLayout one_hole_sheet_layout() {
  const Eigen::Vector4d hole(1.5, 1.0, 2.5, 2.0);
  const mesh::TriMesh sheet = grid_sheet(4.0, 3.0, 0.25, {hole});
  Polycube2D pc;
  pc.domain.width = 4.0;
  pc.domain.height = 3.0;
  pc.domain.holes = {hole};
  pc.domain.hole_loop = {1};
  pc.uv = sheet.V.leftCols(2);
  return base_layout(inset_base_surface(sheet, pc, 0.25, 20));
}

TEST(BaseLayout, FromAnInsetSheet) {
  // The whole chain on a synthetic sheet: inset, then layout.
  const BaseLayout L = one_hole_sheet_layout();
  EXPECT_EQ(L.rectangles.size(), 8u);
  EXPECT_EQ(L.crests.size(), 16u);
  // Every crest segment is covered by boundary edges of the sheet: its
  // vertices on the segment's line span it from end to end.
  const std::vector<int> bnd = boundary_vertices(L.sheet);
  for (const auto& c : L.crests) {
    const int axis = c.a.x() == c.b.x() ? 0 : 1;  // the fixed coordinate
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (int v : bnd) {
      const double t = L.uv(v, 1 - axis);
      if (L.uv(v, axis) == c.a(axis) && t >= c.a(1 - axis) && t <= c.b(1 - axis)) lo = std::min(lo, t), hi = std::max(hi, t);
    }
    EXPECT_EQ(lo, c.a(1 - axis)) << "crest of rectangle " << c.rectangle << " side " << c.side;
    EXPECT_EQ(hi, c.b(1 - axis)) << "crest of rectangle " << c.rectangle << " side " << c.side;
  }
}

// A lid's rectangle is halved in the direction asked, a crest face's along
// its segment only; the layout cut by the lines has the halves.
TEST(BaseLayout, LinesHalvingFacesCutTheirRectangles) {
  const BaseLayout L = one_hole_sheet_layout();
  ASSERT_EQ(L.rectangles.size(), 8u);
  // Rectangle 0 is the bottom left one; its bottom side (0) lies on M's boundary.
  const auto horizontal = std::find_if(L.crests.begin(), L.crests.end(),
                                       [](const CrestSegment& c) { return c.rectangle == 0 && c.side == 0; });
  ASSERT_NE(horizontal, L.crests.end());
  VolumeParam vp;
  vp.face_origins = {{0, -1}, {horizontal->rectangle, static_cast<int>(horizontal - L.crests.begin())}};
  const Eigen::Vector4d& lid = L.rectangles[0];
  const Eigen::Vector4d& crest = L.rectangles[static_cast<std::size_t>(horizontal->rectangle)];
  const GridLines lines = lines_halving_faces(L, vp, {{0, 1}, {1, 0}, {1, 1}});
  ASSERT_EQ(lines.u.size(), 1u);  // the crest face along its segment; across it none
  ASSERT_EQ(lines.v.size(), 1u);  // the lid across v
  EXPECT_DOUBLE_EQ(lines.u[0], 0.5 * (crest(0) + crest(2)));
  EXPECT_DOUBLE_EQ(lines.v[0], 0.5 * (lid(1) + lid(3)));
  const BaseLayout finer = with_more_lines(L, lines);
  EXPECT_EQ(finer.rectangles.size(), 15u);  // 4 x 4 less the hole's cell: both lines pass beside the hole
  EXPECT_EQ(finer.extra.u.size(), 1u);
  EXPECT_EQ(finer.crests.size(), 20u);  // the outer sides each line reaches cut once more: 16 + 2 + 2
}

// ---------------------------------------------------------------- build_volume_param options

TEST(BuildVolumeParam, OptionValidation) {
  DecompositionMesh H;
  H.num_surfaces = 2;  // w0 must lie in (0.5, 1)
  H.tets.V = Eigen::MatrixXd::Zero(4, 3);
  WField w;
  w.w = Eigen::VectorXd::Zero(3);  // of another mesh: the last check, after the options
  const BaseLayout layout;
  const std::vector<double> params{0.0, 0.5, 1.0};
  auto message = [&](const VolumeParamOptions& o, const std::vector<double>& p) -> std::string {
    try {
      build_volume_param(H, w, layout, p, o);
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::BadInput) << e.what();
      return e.what();
    }
    return "no exception";
  };
  auto has = [](const std::string& s, const char* what) { return s.find(what) != std::string::npos; };
  // The message for the default options with one of them changed.
  auto with = [&](auto change) {
    VolumeParamOptions o;
    change(o);
    return message(o, params);
  };
  const VolumeParamOptions o;
  EXPECT_TRUE(has(message(o, params), "w-field belongs to another mesh"));  // the options themselves pass
  EXPECT_TRUE(has(with([](VolumeParamOptions& x) { x.strategy = 3; }), "strategy"));
  EXPECT_TRUE(has(with([](VolumeParamOptions& x) { x.strategy = 0; }), "strategy"));
  EXPECT_TRUE(has(message(o, {0.0, 1.0}), "sample parameters"));
  EXPECT_TRUE(has(message(o, {0.1, 0.5, 1.0}), "sample parameters"));
  EXPECT_TRUE(has(message(o, {0.0, 0.5, 0.9}), "sample parameters"));
  for (double w0 : {0.3, 0.5, 1.0, 1.2}) EXPECT_TRUE(has(with([w0](VolumeParamOptions& x) { x.w0 = w0; }), "w0")) << w0;
  EXPECT_TRUE(has(with([](VolumeParamOptions& x) { x.w0 = 0.8; }), "w-field belongs to another mesh"));
  EXPECT_TRUE(has(with([](VolumeParamOptions& x) { x.theta = 0.0; }), "theta"));
}

}  // namespace

// ---------------------------------------------------------------- orient_block

namespace {

// m^3 samples of the unit cube, first direction fastest; `flip_i` lists the
// pairs of i-columns exchanged (every j, k).
SampledBlock cube_block(int m, const std::vector<std::pair<int, int>>& flip_i = {}) {
  SampledBlock b;
  b.samples.resize(m * m * m, 3);
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) b.samples.row(i + m * (j + m * k)) = Eigen::RowVector3d(i, j, k) / (m - 1.0);
  for (const auto& [a, c] : flip_i)
    for (int k = 0; k < m; ++k)
      for (int j = 0; j < m; ++j) b.samples.row(a + m * (j + m * k)).swap(b.samples.row(c + m * (j + m * k)));
  return b;
}

}  // namespace

TEST(OrientBlock, AnInsideOutBlockIsMirroredAndAFoldAtItsCentreIsNot) {
  const int m = 7, cells = (m - 1) * (m - 1) * (m - 1);
  {  // The cube with its first direction reversed: every cell folded until mirrored.
    SampledBlock b = cube_block(m, {{0, 6}, {1, 5}, {2, 4}});
    b.side_label = {0, -1, -1, -1, -1, -1};
    orient_block(b, m);
    EXPECT_TRUE(b.mirrored);
    EXPECT_EQ(b.folded, 0);
    EXPECT_EQ(b.side_label[1], 0);  // the side moved with the direction
  }
  {  // Columns 2 and 4 exchanged: the cells i = 2 and 3 of every row fold (2
     // of 6). The centre's difference at(4) - at(2) is reversed, which used to
     // mirror the whole block: then 4 of 6 folded.
    SampledBlock b = cube_block(m, {{2, 4}});
    orient_block(b, m);
    EXPECT_FALSE(b.mirrored);
    EXPECT_EQ(b.folded, cells / 3);
  }
  {  // A regular block is left alone.
    SampledBlock b = cube_block(m);
    orient_block(b, m);
    EXPECT_FALSE(b.mirrored);
    EXPECT_EQ(b.folded, 0);
  }
}

namespace {

// An L-shaped block: the unit box without its quarter x > 0.5, y > 0.5.
mesh::TetMesh l_block() {
  const mesh::TetMesh box = param_test::box_tets(4, 4, 1);
  mesh::TetMesh L;
  L.V = box.V;
  std::vector<int> kept;
  for (Eigen::Index c = 0; c < box.T.rows(); ++c) {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) centre += box.V.row(box.T(c, k)).transpose() / 4.0;
    if (!(centre.x() > 0.5 && centre.y() > 0.5)) kept.push_back(static_cast<int>(c));
  }
  L.T.resize(static_cast<Eigen::Index>(kept.size()), 4);
  for (std::size_t i = 0; i < kept.size(); ++i) L.T.row(static_cast<Eigen::Index>(i)) = box.T.row(kept[i]);
  return L;
}

}  // namespace

// Rays from one arm of the L to the other that pass below the re-entrant
// edge stay inside, in one step each: the hinted walk of a step may cross
// the notch, which does not make the ray leave (before: 822 of 2,967 such
// rays were refused as leaving the mesh). A ray through the notch leaves.
TEST(FieldProbe, RaysPastAReEntrantEdgeReachTheirLevel) {
  LinearField f(l_block());
  int rays = 0;
  for (double sx = 0.3; sx < 0.5; sx += 0.03)
    for (double sy = 0.52; sy < 0.7; sy += 0.03)
      for (double ex = 0.52; ex < 0.7; ex += 0.03)
        for (double ey = 0.3; ey < 0.5; ey += 0.03) {
          const Eigen::Vector3d s(sx, sy, 0.5), e(ex, ey, 0.5);
          if (sy + (0.5 - sx) / (ex - sx) * (ey - sy) > 0.499) continue;  // through the notch
          const Eigen::Vector3d d = (e - s).normalized();
          f.a = -d;  // w falls along the ray at rate 1
          f.u = f.mesh.V * f.a;
          f.grad = vertex_gradients(f.mesh.V, f.mesh.T, f.u);
          const FieldProbe probe(f.mesh.V, f.mesh.T, f.topo, f.u, f.grad);
          const double length = 1.1 * (e - s).norm();
          int hint = -1;
          const Eigen::Vector3d x = probe.ray_to_level(s, d, f.a.dot(s) - length, (e - s).norm(), 2.0, &hint);
          ASSERT_NEAR((x - s).norm(), length, 1e-9) << "from " << s.transpose() << " to " << e.transpose();
          ++rays;
        }
  EXPECT_GT(rays, 900);
  const Eigen::Vector3d s(0.45, 0.6, 0.5), d = Eigen::Vector3d(1.0, -1.0, 0.0).normalized();  // x + y = 1.05: the notch
  f.a = -d;
  f.u = f.mesh.V * f.a;
  f.grad = vertex_gradients(f.mesh.V, f.mesh.T, f.u);
  const FieldProbe probe(f.mesh.V, f.mesh.T, f.topo, f.u, f.grad);
  try {
    probe.ray_to_level(s, d, f.a.dot(s) - 0.3, 0.01, 2.0);
    ADD_FAILURE() << "a ray through the notch was not refused";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::CheckFailed);
    EXPECT_NE(std::string(e.what()).find("leaves the mesh"), std::string::npos) << e.what();
  }
}
