// The non-uniform rules of refine_cage (NURCC: knot intervals on edges,
// opposite edges of a face equal) against non-uniform cubic B-splines: on a
// closed grid of valence-4 vertices the refined cage is knot insertion at
// the middle of every interval, so the two cages' B-spline surfaces agree;
// a crease loop's polygon refines as its B-spline curve; around
// extraordinary vertices the opposite-edge rule holds after every step.
// (Equal intervals: refine_test.cpp, against OpenSubdiv.)
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <map>
#include <random>

#include "igaprep/spline/tnurcc_refine.h"
#include "tnurcc/tnurcc_models.h"

namespace {

using namespace igaprep::spline;

// A periodic grid n x m (a torus's topology): vertex (i, j) = i + n j;
// s-edges of column i carry ds[i], t-edges of row j carry dt[j].
struct PeriodicGrid {
  int n = 0, m = 0;
  std::vector<double> ds, dt;
  Cage cage;
  int vertex(int i, int j) const { return ((i % n + n) % n) + n * ((j % m + m) % m); }
};

PeriodicGrid periodic_grid(int n, int m, std::mt19937& rng) {
  std::uniform_real_distribution<double> interval(0.4, 2.5), noise(-0.2, 0.2);
  PeriodicGrid g;
  g.n = n;
  g.m = m;
  for (int i = 0; i < n; ++i) g.ds.push_back(interval(rng));
  for (int j = 0; j < m; ++j) g.dt.push_back(interval(rng));
  g.cage.points.resize(n * m, 3);
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      const double a = 2 * M_PI * i / n, b = 2 * M_PI * j / m;
      g.cage.points.row(i + n * j) << (3 + std::cos(b)) * std::cos(a) + noise(rng),
          (3 + std::cos(b)) * std::sin(a) + noise(rng), std::sin(b) + noise(rng);
    }
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i)
      g.cage.faces.push_back({{g.vertex(i, j), g.vertex(i + 1, j), g.vertex(i + 1, j + 1), g.vertex(i, j + 1)}});
  build_cage_edges(g.cage);
  for (auto& e : g.cage.edges) {
    const int a = e.vertices[0], b = e.vertices[1];
    const bool along_s = a / n == b / n;  // same row
    e.interval = along_s ? g.ds[(b % n == (a % n + 1) % n) ? a % n : b % n] : g.dt[(b / n == (a / n + 1) % m) ? a / n : b / n];
  }
  return g;
}

// The cubic B-spline of a periodic polygon with knot intervals d (d[k]
// between points k and k + 1): point k's function has the knots at points
// k - 2 .. k + 2.
struct PeriodicBasis {
  std::vector<double> d;
  double knot(int k) const {  // the knot at point k, any integer k
    const int n = static_cast<int>(d.size());
    double length = 0.0;
    for (double x : d) length += x;
    const int wraps = (k >= 0 ? k / n : -((-k + n - 1) / n));
    double u = wraps * length;
    for (int i = 0; i < k - wraps * n; ++i) u += d[i];
    return u;
  }
  // The value of point k's function at u (Cox-de Boor on its five knots).
  double value(int k, double u) const {
    double t[5], N[4];
    for (int a = 0; a < 5; ++a) t[a] = knot(k - 2 + a);
    for (int a = 0; a < 4; ++a) N[a] = (u >= t[a] && u < t[a + 1]) ? 1.0 : 0.0;
    for (int p = 1; p <= 3; ++p)
      for (int a = 0; a < 4 - p; ++a)
        N[a] = (u - t[a]) / (t[a + p] - t[a]) * N[a] + (t[a + p + 1] - u) / (t[a + p + 1] - t[a + 1]) * N[a + 1];
    return N[0];
  }
  // The points whose functions are non-zero at u in [knot(0), knot(n)).
  std::vector<std::pair<int, double>> at(double u) const {
    int a = 0;
    while (knot(a + 1) <= u) ++a;
    std::vector<std::pair<int, double>> out;
    for (int k = a - 1; k <= a + 2; ++k) out.emplace_back(k, value(k, u));
    return out;
  }
};

// The tensor-product surface of a periodic grid's points at (u, v).
Eigen::RowVector3d surface(const PeriodicBasis& bs, const PeriodicBasis& bt, int n, int m,
                           const std::function<Eigen::RowVector3d(int, int)>& point, double u, double v) {
  Eigen::RowVector3d x = Eigen::RowVector3d::Zero();
  for (const auto& [i, ni] : bs.at(u))
    for (const auto& [j, nj] : bt.at(v)) x += ni * nj * point(((i % n) + n) % n, ((j % m) + m) % m);
  return x;
}

int edge_between(const Cage& c, int a, int b) {
  for (size_t e = 0; e < c.edges.size(); ++e)
    if ((c.edges[e].vertices[0] == a && c.edges[e].vertices[1] == b) ||
        (c.edges[e].vertices[0] == b && c.edges[e].vertices[1] == a))
      return static_cast<int>(e);
  return -1;
}

// The refined grid's vertex (I, J) of 2n x 2m: vertex, edge and face points
// as refine_cage numbers them.
int refined_vertex(const PeriodicGrid& g, int I, int J) {
  const int nf = static_cast<int>(g.cage.faces.size()), ne = static_cast<int>(g.cage.edges.size());
  I = ((I % (2 * g.n)) + 2 * g.n) % (2 * g.n);
  J = ((J % (2 * g.m)) + 2 * g.m) % (2 * g.m);
  const int i = I / 2, j = J / 2;
  if (I % 2 == 0 && J % 2 == 0) return nf + ne + g.vertex(i, j);
  if (I % 2 == 1 && J % 2 == 1) return i + g.n * j;  // face (i, j)
  const int other = I % 2 == 1 ? g.vertex(i + 1, j) : g.vertex(i, j + 1);
  return nf + edge_between(g.cage, g.vertex(i, j), other);
}

// A box's cage (one patch, two elements) with one knot interval per axis,
// so opposite edges of every face agree: eight valence-3 vertices.
Cage box_with_axis_intervals() {
  CageOptions smooth;
  smooth.crease_angle = 180.0;
  Cage box = surface_cage(tnurcc_test::boxes(1, 2), 0, smooth);
  for (auto& e : box.edges) {
    const Eigen::RowVector3d d = (box.points.row(e.vertices[1]) - box.points.row(e.vertices[0])).cwiseAbs();
    int axis = 0;
    d.maxCoeff(&axis);
    e.interval = std::array<double, 3>{{1.0, 0.6, 1.7}}[axis];
  }
  return box;
}

// The s-edges of one row of a periodic grid made a crease loop.
void crease_row(const PeriodicGrid& g, int row, Cage& cage) {
  for (auto& e : cage.edges)
    if (e.vertices[0] / g.n == row && e.vertices[1] / g.n == row) e.sharpness = kInfiniteSharpness;
}

TEST(Nurcc, RefinedPeriodicGridIsKnotInsertionAtTheMiddles) {
  std::mt19937 rng(3);
  const PeriodicGrid g = periodic_grid(7, 6, rng);
  const Cage r = refine_cage(g.cage);
  EXPECT_TRUE(opposite_edge_violations(r).empty());
  PeriodicBasis bs{g.ds}, bt{g.dt}, rs, rt;
  for (double d : g.ds) rs.d.insert(rs.d.end(), {d / 2, d / 2});
  for (double d : g.dt) rt.d.insert(rt.d.end(), {d / 2, d / 2});
  // The child edges carry the halved intervals.
  for (int J = 0; J < 2 * g.m; ++J)
    for (int I = 0; I < 2 * g.n; ++I) {
      const int a = refined_vertex(g, I, J);
      EXPECT_NEAR(r.edges[edge_between(r, a, refined_vertex(g, I + 1, J))].interval, rs.d[I], 1e-15);
      EXPECT_NEAR(r.edges[edge_between(r, a, refined_vertex(g, I, J + 1))].interval, rt.d[J], 1e-15);
    }
  auto parent = [&](int i, int j) { return Eigen::RowVector3d(g.cage.points.row(g.vertex(i, j))); };
  auto child = [&](int I, int J) { return Eigen::RowVector3d(r.points.row(refined_vertex(g, I, J))); };
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0, size = 0.0;
  for (int k = 0; k < 300; ++k) {
    const double u = unit(rng) * bs.knot(g.n), v = unit(rng) * bt.knot(g.m);
    const Eigen::RowVector3d x = surface(bs, bt, g.n, g.m, parent, u, v);
    worst = std::max(worst, (x - surface(rs, rt, 2 * g.n, 2 * g.m, child, u, v)).norm());
    size = std::max(size, x.norm());
  }
  EXPECT_GT(size, 1.0);
  EXPECT_LT(worst, 1e-12 * size) << worst;
}


// Row 2's s-edges made a crease: a closed crease loop whose vertices each
// have two crease edges. Its polygon refines as its own cubic B-spline curve.
TEST(Nurcc, CreaseLoopRefinesAsItsCurve) {
  std::mt19937 rng(8);
  PeriodicGrid g = periodic_grid(8, 5, rng);
  const int row = 2;
  crease_row(g, row, g.cage);
  const Cage r = refine_cage(g.cage);
  EXPECT_TRUE(opposite_edge_violations(r).empty());
  PeriodicBasis bs{g.ds}, rs;
  for (double d : g.ds) rs.d.insert(rs.d.end(), {d / 2, d / 2});
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0;
  for (int k = 0; k < 200; ++k) {
    const double u = unit(rng) * bs.knot(g.n);
    Eigen::RowVector3d x = Eigen::RowVector3d::Zero(), y = Eigen::RowVector3d::Zero();
    for (const auto& [i, w] : bs.at(u)) x += w * g.cage.points.row(g.vertex(i, row));
    for (const auto& [I, w] : rs.at(u)) y += w * r.points.row(refined_vertex(g, I, 2 * row));
    worst = std::max(worst, (x - y).norm());
  }
  EXPECT_LT(worst, 1e-12) << worst;
  // The crease stays a crease: its halves, and nothing else.
  int creases = 0;
  for (const auto& e : r.edges) creases += e.sharpness > 0.0;
  EXPECT_EQ(creases, 2 * g.n);
}

// A box's cage with a different interval per axis (opposite edges of every
// face equal): eight extraordinary vertices of valence 3. Two steps keep
// the opposite-edge rule, every child point is an affine combination (a
// translated cage refines to the translated refinement), and the intervals
// halve per axis.
TEST(Nurcc, ExtraordinaryVerticesKeepTheOppositeEdgeRule) {
  const Cage box = box_with_axis_intervals();
  ASSERT_TRUE(opposite_edge_violations(box).empty());
  const Cage once = refine_cage(box), twice = refine_cage(once);
  EXPECT_TRUE(opposite_edge_violations(once).empty());
  EXPECT_TRUE(opposite_edge_violations(twice).empty());
  Cage moved = box;
  moved.points.rowwise() += Eigen::RowVector3d(3.0, -2.0, 0.5);
  const Cage r = refine_cage(moved);
  EXPECT_LT((r.points.rowwise() - Eigen::RowVector3d(3.0, -2.0, 0.5) - once.points).cwiseAbs().maxCoeff(), 1e-12);
  std::map<double, int> intervals;
  for (const auto& e : twice.edges) ++intervals[e.interval];
  EXPECT_EQ(intervals.size(), 3u);
  EXPECT_DOUBLE_EQ(intervals.begin()->first, 0.6 / 4);
  EXPECT_DOUBLE_EQ(intervals.rbegin()->first, 1.7 / 4);
}


// limit_positions with unequal intervals: at valence-4 vertices the
// B-spline surface at the vertex's knots; along a crease loop its curve at
// the knots.
TEST(NurccLimit, RegularVerticesAndCreasesAreTheSplinesAtTheKnots) {
  std::mt19937 rng(21);
  PeriodicGrid g = periodic_grid(7, 6, rng);
  const int row = 3;
  Cage creased = g.cage;
  crease_row(g, row, creased);
  const Eigen::MatrixXd smooth = limit_positions(g.cage), crease = limit_positions(creased);
  PeriodicBasis bs{g.ds}, bt{g.dt};
  auto parent = [&](int i, int j) { return Eigen::RowVector3d(g.cage.points.row(g.vertex(i, j))); };
  double worst = 0.0, worst_crease = 0.0;
  for (int j = 0; j < g.m; ++j)
    for (int i = 0; i < g.n; ++i)
      worst = std::max(worst, (smooth.row(g.vertex(i, j)) -
                               surface(bs, bt, g.n, g.m, parent, bs.knot(i), bt.knot(j))).norm());
  for (int i = 0; i < g.n; ++i) {
    Eigen::RowVector3d x = Eigen::RowVector3d::Zero();
    for (const auto& [k, w] : bs.at(bs.knot(i))) x += w * g.cage.points.row(g.vertex(k, row));
    worst_crease = std::max(worst_crease, (crease.row(g.vertex(i, row)) - x).norm());
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_LT(worst_crease, 1e-12);
}

// At extraordinary vertices (valence 3, a different interval per axis) the
// limit comes from the ring's stationary refinement: refining the cage
// first gives the same limit at every vertex's child, to round-off.
TEST(NurccLimit, LimitPositionsDoNotChangeUnderRefinement) {
  Cage box = box_with_axis_intervals();
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> noise(-0.05, 0.05);
  for (int v = 0; v < box.points.rows(); ++v) box.points.row(v) += Eigen::RowVector3d(noise(rng), noise(rng), noise(rng));
  ASSERT_TRUE(opposite_edge_violations(box).empty());
  const Cage once = refine_cage(box);
  const Eigen::MatrixXd before = limit_positions(box), after = limit_positions(once);
  const int offset = static_cast<int>(box.faces.size() + box.edges.size());
  double worst = 0.0, moved = 0.0;
  for (int v = 0; v < box.points.rows(); ++v) {
    worst = std::max(worst, (before.row(v) - after.row(offset + v)).norm());
    moved = std::max(moved, (before.row(v) - box.points.row(v)).norm());
  }
  EXPECT_GT(moved, 0.01);  // the limit is not the cage
  EXPECT_LT(worst, 1e-12) << worst;
}


// The weights behind refine_cage and limit_positions: each row an affine
// combination (rows sum to 1), local (a limit row at a valence-3 vertex
// reaches its ring's refinement only), and the points they give.
TEST(NurccLimit, WeightsAreAffineAndLocal) {
  std::mt19937 rng(9);
  PeriodicGrid g = periodic_grid(6, 6, rng);
  CageOptions smooth;
  smooth.crease_angle = 180.0;
  for (const Cage& c : {g.cage, surface_cage(tnurcc_test::boxes(1, 2), 0, smooth)}) {
    const CageRefinement r = refinement(c);
    const StencilMatrix L = limit_position_weights(c);
    EXPECT_LT((r.child.points - r.weights * c.points).cwiseAbs().maxCoeff(), 1e-15);
    EXPECT_LT((limit_positions(c) - L * c.points).cwiseAbs().maxCoeff(), 1e-15);
    const Eigen::VectorXd ones = Eigen::VectorXd::Ones(c.points.rows());
    EXPECT_LT((r.weights * ones - Eigen::VectorXd::Ones(r.weights.rows())).cwiseAbs().maxCoeff(), 1e-14);
    EXPECT_LT((L * ones - Eigen::VectorXd::Ones(L.rows())).cwiseAbs().maxCoeff(), 1e-12);
    for (int v = 0; v < L.outerSize(); ++v) EXPECT_LE(L.row(v).nonZeros(), 2 * 13 + 1) << v;
  }
}


// Limit points on a dyadic grid per face: OpenSubdiv's with equal
// intervals, the B-spline surface's on a closed grid with unequal ones, and
// with extraordinary vertices the same whether the cage is refined first.
TEST(NurccDyadic, EqualIntervalsGiveOpenSubdivsLimit) {
  CageOptions smooth;
  smooth.crease_angle = 180.0;
  for (const Cage& c : {surface_cage(tnurcc_test::boxes(1, 2), 0, smooth), surface_cage(tnurcc_test::boxes(2, 2), 0)}) {
    const DyadicLimit d = dyadic_limit(c, 2);
    ASSERT_EQ(d.at.size(), c.faces.size() * 25);
    const Eigen::MatrixXd mine = d.weights * c.points, osd = limit_stencils(c, d.at).value * c.points;
    EXPECT_LT((mine - osd).cwiseAbs().maxCoeff(), 1e-12);
  }
}

TEST(NurccDyadic, UnequalIntervalsOnAGridGiveTheBSplineSurface) {
  std::mt19937 rng(17);
  const PeriodicGrid g = periodic_grid(6, 5, rng);
  const DyadicLimit d = dyadic_limit(g.cage, 2);
  const Eigen::MatrixXd x = d.weights * g.cage.points;
  PeriodicBasis bs{g.ds}, bt{g.dt};
  auto parent = [&](int i, int j) { return Eigen::RowVector3d(g.cage.points.row(g.vertex(i, j))); };
  double worst = 0.0;
  for (size_t k = 0; k < d.at.size(); ++k) {
    const int i = d.at[k].face % g.n, j = d.at[k].face / g.n;
    const double u = bs.knot(i) + d.at[k].s * g.ds[i], v = bt.knot(j) + d.at[k].t * g.dt[j];
    worst = std::max(worst, (x.row(static_cast<int>(k)) - surface(bs, bt, g.n, g.m, parent, u, v)).norm());
  }
  EXPECT_LT(worst, 1e-12) << worst;
}

TEST(NurccDyadic, ExtraordinaryVerticesAgreeAcrossLevels) {
  const Cage box = box_with_axis_intervals();
  const DyadicLimit coarse = dyadic_limit(box, 2), fine = dyadic_limit(refine_cage(box), 1);
  const Eigen::MatrixXd a = coarse.weights * box.points, b = fine.weights * refine_cage(box).points;
  // Child face 4 f + k covers parent face f's quarter at corner k (refine_cage's numbering).
  const double s0[4] = {0, 1, 1, 0}, t0[4] = {0, 0, 1, 1};
  double worst = 0.0;
  for (size_t r = 0; r < fine.at.size(); ++r) {
    const LimitLocation& l = fine.at[r];
    const int f = l.face / 4, k = l.face % 4;
    // Child (s, t) along (vertex k -> edge k, vertex k -> edge k - 1) in the parent's corners' frame.
    const Eigen::Vector2d corner(s0[k], t0[k]), along_s = 0.5 * (Eigen::Vector2d(s0[(k + 1) % 4], t0[(k + 1) % 4]) - corner),
                          along_t = 0.5 * (Eigen::Vector2d(s0[(k + 3) % 4], t0[(k + 3) % 4]) - corner);
    const Eigen::Vector2d st = corner + l.s * along_s + l.t * along_t;
    const int i = static_cast<int>(std::lround(st[0] * 4)), j = static_cast<int>(std::lround(st[1] * 4));
    worst = std::max(worst, (b.row(static_cast<int>(r)) - a.row(f * 25 + i + 5 * j)).norm());
  }
  EXPECT_LT(worst, 1e-12) << worst;
}

// Limit normals from limit_tangent_weights: the B-spline surface's on a
// grid with unequal intervals, OpenSubdiv's (outward) at every smooth vertex
// of a uniform box (the valence-3 ones included), and the same before and
// after a refinement around valence-3 vertices with unequal intervals.
Eigen::MatrixXd vertex_normals(const Cage& c) {
  const VertexTangentWeights t = limit_tangent_weights(c);
  const Eigen::MatrixXd a = t.first * c.points, b = t.second * c.points;
  Eigen::MatrixXd n(c.points.rows(), 3);
  for (int v = 0; v < n.rows(); ++v) {
    const Eigen::Vector3d x = Eigen::Vector3d(a.row(v)).cross(Eigen::Vector3d(b.row(v)));
    n.row(v) = x.norm() > 0.0 ? Eigen::RowVector3d(x.normalized()) : Eigen::RowVector3d::Zero();
  }
  return n;
}

TEST(NurccTangents, GridTangentsAreTheBSplineDerivatives) {
  std::mt19937 rng(23);
  const PeriodicGrid g = periodic_grid(6, 5, rng);
  const VertexTangentWeights t = limit_tangent_weights(g.cage);
  const Eigen::MatrixXd a = t.first * g.cage.points, b = t.second * g.cage.points;
  PeriodicBasis bs{g.ds}, bt{g.dt};
  auto parent = [&](int i, int j) { return Eigen::RowVector3d(g.cage.points.row(g.vertex(i, j))); };
  const double h = 1e-5;
  double worst = 0.0;
  for (int j = 0; j < g.m; ++j)
    for (int i = 0; i < g.n; ++i) {
      const double u = bs.knot(i) + (i == 0 ? bs.knot(g.n) : 0.0), v = bt.knot(j) + (j == 0 ? bt.knot(g.m) : 0.0);
      auto S = [&](double uu, double vv) { return surface(bs, bt, g.n, g.m, parent, uu, vv); };
      const Eigen::RowVector3d du = (S(u + h, v) - S(u - h, v)) / (2 * h), dv = (S(u, v + h) - S(u, v - h)) / (2 * h);
      // Spokes 0 and 1 run along +-u and +-v in some order: match each tangent to one derivative.
      const int k = g.vertex(i, j);
      for (const Eigen::RowVector3d& x : {Eigen::RowVector3d(a.row(k)), Eigen::RowVector3d(b.row(k))}) {
        const double e = std::min({(x - du).norm(), (x + du).norm(), (x - dv).norm(), (x + dv).norm()});
        worst = std::max(worst, e / std::max(du.norm(), dv.norm()));
      }
    }
  EXPECT_LT(worst, 1e-7) << worst;
}

TEST(NurccTangents, EqualIntervalsGiveOpenSubdivsNormals) {
  CageOptions smooth;
  smooth.crease_angle = 180.0;
  const Cage c = surface_cage(tnurcc_test::boxes(1, 2), 0, smooth);
  const Eigen::MatrixXd mine = vertex_normals(c);
  std::vector<LimitLocation> at;
  for (int v = 0; v < c.points.rows(); ++v)
    for (size_t f = 0; f < c.faces.size(); ++f)
      for (int k = 0; k < 4; ++k)
        if (c.faces[f][k] == v && at.size() == static_cast<size_t>(v)) {
          const double s[4] = {0, 1, 1, 0}, t[4] = {0, 0, 1, 1};
          at.push_back({static_cast<int>(f), s[k], t[k]});
        }
  const LimitValues osd = limit_values(limit_stencils(c, at), c.points);
  double worst = 0.0;
  for (int v = 0; v < c.points.rows(); ++v) worst = std::max(worst, (mine.row(v) - osd.normal.row(v)).norm());
  EXPECT_LT(worst, 1e-9) << worst;
}

TEST(NurccTangents, NormalsAtExtraordinaryVerticesDoNotChangeUnderRefinement) {
  Cage box = box_with_axis_intervals();
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> noise(-0.03, 0.03);
  for (int v = 0; v < box.points.rows(); ++v) box.points.row(v) += Eigen::RowVector3d(noise(rng), noise(rng), noise(rng));
  const Cage once = refine_cage(box);
  const Eigen::MatrixXd before = vertex_normals(box), after = vertex_normals(once);
  const Eigen::RowVector3d centre = box.points.colwise().mean();
  const int offset = static_cast<int>(box.faces.size() + box.edges.size());
  double worst = 0.0;
  for (int v = 0; v < box.points.rows(); ++v) {
    worst = std::max(worst, (before.row(v) - after.row(offset + v)).norm());
    EXPECT_GT(before.row(v).dot(box.points.row(v) - centre), 0.0) << v;  // outward
  }
  EXPECT_LT(worst, 1e-9) << worst;
}

}  // namespace
