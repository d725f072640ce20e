// Gradient tracing through tets and over triangles.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "igaprep/core/error.h"
#include "igaprep/param/harmonic_field.h"
#include "igaprep/param/stiffness_matrix.h"
#include "igaprep/param/tet_topology.h"
#include "igaprep/param/trace_gradient.h"
#include "param_meshes.h"

using namespace igaprep::param;

namespace {

// Angle in degrees between a and b.
double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180.0 / M_PI;
}

}  // namespace

TEST(Topology, NeighboursAreMutualAndBoundaryIsTheSurface) {
  const auto m = param_test::box_tets(4, 3, 5);
  const TetTopology topo = build_tet_topology(m.T, m.V.rows());
  int boundary = 0;
  for (Eigen::Index c = 0; c < m.T.rows(); ++c)
    for (int i = 0; i < 4; ++i) {
      const int n = topo.neighbor(c, i);
      if (n < 0) {
        ++boundary;
        continue;
      }
      ASSERT_EQ(topo.neighbor(n, topo.neighbor_facet(c, i)), c);
      ASSERT_EQ(topo.neighbor_facet(n, topo.neighbor_facet(c, i)), i);
    }
  EXPECT_EQ(boundary, 2 * 2 * (4 * 3 + 3 * 5 + 4 * 5));  // two triangles per boundary square
  // A facet shared by three tets is non-manifold.
  Eigen::MatrixXi T(3, 4);
  T << 0, 1, 2, 3, 0, 1, 2, 4, 0, 1, 2, 5;
  EXPECT_THROW(build_tet_topology(T, 6), igaprep::Error);
}

TEST(Trace, ShellTracesAreRadialAndEndOnTheInnerSphere) {
  // Fine inner sphere (level 5: flat triangles stay within 2e-4 of r = 1).
  const auto s = param_test::spherical_shell(5, 6);
  const auto& m = s.mesh;
  const Eigen::VectorXd u = harmonic_field(m.V, m.T, {{s.inner, 1.0}, {s.outer, 0.0}});
  const TetTopology topo = build_tet_topology(m.T, m.V.rows());
  TraceTarget target;
  target.marked = mark_facets(m.T, topo, s.inner_faces);
  const GradientTracer tracer(m.V, m.T, topo, u);
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> U(-1.0, 1.0), R(1.02, 1.98);
  double angle_sum = 0.0, length_sum = 0.0, worst_radius = 0.0;
  int hint = 0, reached = 0;
  for (int i = 0; i < 500; ++i) {
    Eigen::Vector3d dir;
    do dir = Eigen::Vector3d(U(rng), U(rng), U(rng));
    while (dir.norm() > 1.0 || dir.norm() < 0.1);
    const Eigen::Vector3d start = R(rng) * dir.normalized();
    Eigen::Vector4d bary;
    hint = tracer.locate(start, hint, &bary);
    ASSERT_GE(hint, 0) << "start point " << i;
    const TraceResult t = tracer.trace(hint, bary, target);
    ASSERT_EQ(t.status, TraceStatus::Reached) << "trace " << i << ": " << to_string(t.status);
    ++reached;
    ASSERT_GE(t.face, 0);
    EXPECT_LT(t.face, s.inner_faces.rows());
    EXPECT_EQ(t.bary(t.facet), 0.0);  // on the reached facet exactly
    worst_radius = std::max(worst_radius, std::abs(t.end.norm() - 1.0));
    EXPECT_NEAR(t.value, 1.0, 1e-12);  // the inner sphere carries u = 1
    // Radial: each segment against the radial direction at its midpoint.
    for (Eigen::Index k = 0; k + 1 < t.path.rows(); ++k) {
      const Eigen::Vector3d a = t.path.row(k), b = t.path.row(k + 1);
      const double len = (b - a).norm();
      angle_sum += len * angle_deg(b - a, -(a + b));
      length_sum += len;
    }
  }
  const double mean_angle = angle_sum / length_sum;
  std::printf("500 shell traces: mean deviation from radial %.3f deg, worst |r - 1| at the end %.2e\n", mean_angle,
              worst_radius);
  EXPECT_EQ(reached, 500);
  EXPECT_LT(mean_angle, 2.0);
  EXPECT_LT(worst_radius, 1e-3);
}

TEST(Trace, IsoValueTargetInTheShellBothWays) {
  const auto s = param_test::spherical_shell(3, 4);
  const auto& m = s.mesh;
  const Eigen::VectorXd u = harmonic_field(m.V, m.T, {{s.inner, 1.0}, {s.outer, 0.0}});
  const TetTopology topo = build_tet_topology(m.T, m.V.rows());
  const GradientTracer tracer(m.V, m.T, topo, u);
  TraceTarget up, down;
  up.use_iso = down.use_iso = true;
  up.iso = 0.8;
  down.iso = 0.1;
  TraceOptions descend;
  descend.descend = true;
  const Eigen::Vector3d start(0.3, 1.2, -0.5);
  const TraceResult a = tracer.trace(start, up), b = tracer.trace(start, down, descend);
  ASSERT_EQ(a.status, TraceStatus::Reached);
  ASSERT_EQ(b.status, TraceStatus::Reached);
  EXPECT_NEAR(a.value, 0.8, 1e-12);
  EXPECT_NEAR(b.value, 0.1, 1e-12);
  EXPECT_LT(a.end.norm(), start.norm());
  EXPECT_GT(b.end.norm(), start.norm());
  // The field along a +grad trace never decreases.
  for (Eigen::Index k = 0; k + 1 < a.path.rows(); ++k) {
    Eigen::Vector4d b0, b1;
    const int c0 = tracer.locate(a.path.row(k).transpose(), a.cell, &b0);
    const int c1 = tracer.locate(a.path.row(k + 1).transpose(), a.cell, &b1);
    double v0 = 0, v1 = 0;
    for (int j = 0; j < 4; ++j) v0 += b0(j) * u(m.T(c0, j)), v1 += b1(j) * u(m.T(c1, j));
    EXPECT_GE(v1, v0 - 1e-9);
  }
}

TEST(Trace, PassesExactlyThroughEdgesAndVertices) {
  // u = x + y + z on a structured box: traces from lattice points run along
  // the cube diagonals, through tet edges and mesh vertices only.
  const auto m = param_test::box_tets(6, 6, 6);
  Eigen::VectorXd u(m.V.rows());
  for (Eigen::Index i = 0; i < u.size(); ++i) u(i) = m.V.row(i).sum();
  const TetTopology topo = build_tet_topology(m.T, m.V.rows());
  const GradientTracer tracer(m.V, m.T, topo, u);
  TraceTarget target;
  target.use_iso = true;
  target.iso = 2.5;
  for (const Eigen::Vector3d start : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1.0 / 6, 2.0 / 6, 0.5),
                                      Eigen::Vector3d(0.5, 0.5, 0.5), Eigen::Vector3d(0.25, 0.3, 0.41)}) {
    const TraceResult t = tracer.trace(start, target);
    ASSERT_EQ(t.status, TraceStatus::Reached) << to_string(t.status) << " from " << start.transpose();
    EXPECT_NEAR(t.value, 2.5, 1e-12);
    // A straight line along (1,1,1).
    const Eigen::Vector3d expected = start + (2.5 - start.sum()) / 3.0 * Eigen::Vector3d::Ones();
    EXPECT_LE((t.end - expected).norm(), 1e-12) << "from " << start.transpose();
    for (Eigen::Index k = 0; k < t.path.rows(); ++k) {
      const Eigen::Vector3d q = t.path.row(k).transpose() - start;
      EXPECT_LE((q - q.sum() / 3.0 * Eigen::Vector3d::Ones()).norm(), 1e-12);
    }
    EXPECT_GT(t.steps, 0);
  }
}

TEST(Trace, BoundaryBudgetAndStall) {
  const auto m = param_test::box_tets(5, 5, 5, 0.1, 9);
  const TetTopology topo = build_tet_topology(m.T, m.V.rows());
  Eigen::VectorXd u(m.V.rows());
  for (Eigen::Index i = 0; i < u.size(); ++i) u(i) = m.V(i, 0) + 0.3 * m.V(i, 1);
  const GradientTracer tracer(m.V, m.T, topo, u);
  // No target: up the gradient, slides along y = 1 and stops at the edge x = 1, y = 1.
  const TraceResult hit = tracer.trace(Eigen::Vector3d(0.2, 0.4, 0.5), TraceTarget{});
  EXPECT_EQ(hit.status, TraceStatus::HitBoundary);
  EXPECT_NEAR(hit.end.x(), 1.0, 1e-12);
  EXPECT_NEAR(hit.end.y(), 1.0, 1e-12);
  EXPECT_NEAR(hit.end.z(), 0.5, 1e-9);  // the field does not depend on z: the trace keeps its z
  TraceOptions no_slide;
  no_slide.slide_on_boundary = false;
  const TraceResult stop = tracer.trace(Eigen::Vector3d(0.2, 0.4, 0.5), TraceTarget{}, no_slide);
  EXPECT_EQ(stop.status, TraceStatus::HitBoundary);
  EXPECT_TRUE(std::abs(stop.end.x() - 1.0) < 1e-12 || std::abs(stop.end.y() - 1.0) < 1e-12);
  EXPECT_GE(stop.facet, 0);
  EXPECT_EQ(topo.neighbor(stop.cell, stop.facet), -1);
  // A tiny budget.
  TraceOptions small;
  small.max_steps = 3;
  TraceTarget far;
  far.use_iso = true;
  far.iso = 1.2;
  const TraceResult budget = tracer.trace(Eigen::Vector3d(0.05, 0.1, 0.5), far, small);
  EXPECT_EQ(budget.status, TraceStatus::StepBudget);
  EXPECT_LE(budget.steps, 3);
  // A constant field: nowhere to go (and a target it is already past is reached at once).
  const GradientTracer flat(m.V, m.T, topo, Eigen::VectorXd::Constant(m.V.rows(), 1.0));
  EXPECT_EQ(flat.trace(Eigen::Vector3d(0.5, 0.5, 0.5), far).status, TraceStatus::Stalled);
  TraceTarget below;
  below.use_iso = true;
  below.iso = 0.5;
  const TraceResult at_once = flat.trace(Eigen::Vector3d(0.5, 0.5, 0.5), below);
  EXPECT_EQ(at_once.status, TraceStatus::Reached);
  EXPECT_EQ(at_once.path.rows(), 1);
  // A start outside the mesh.
  EXPECT_THROW(tracer.trace(Eigen::Vector3d(1.5, 0.5, 0.5), far), igaprep::Error);
}

TEST(Trace, InteriorMaximumStallsInsteadOfLooping) {
  // u = -(x-c)^2 - ... has a maximum inside; +grad traces must stop there, stalled.
  const auto m = param_test::box_tets(8, 8, 8, 0.12, 4);
  const TetTopology topo = build_tet_topology(m.T, m.V.rows());
  Eigen::VectorXd u(m.V.rows());
  for (Eigen::Index i = 0; i < u.size(); ++i) u(i) = -(m.V.row(i).array() - 0.45).square().sum();
  const GradientTracer tracer(m.V, m.T, topo, u);
  TraceTarget none;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(0.02, 0.98);
  for (int i = 0; i < 50; ++i) {
    const TraceResult t = tracer.trace(Eigen::Vector3d(U(rng), U(rng), U(rng)), none);
    EXPECT_EQ(t.status, TraceStatus::Stalled) << i;
    EXPECT_LT((t.end - Eigen::Vector3d::Constant(0.45)).norm(), 0.3) << i;
    EXPECT_LT(t.steps, 200) << i;
  }
}

TEST(Trace, TriangleMeshPlanarAndCurved) {
  // Planar: u = x + y on a square, through vertices and edges, to u = 1.5.
  const auto sq = param_test::square_tris(8);
  Eigen::VectorXd u(sq.V.rows());
  for (Eigen::Index i = 0; i < u.size(); ++i) u(i) = sq.V(i, 0) + sq.V(i, 1);
  const TetTopology topo = build_tet_topology(sq.F, sq.V.rows());
  const GradientTracer tracer(sq.V, sq.F, topo, u);
  TraceTarget target;
  target.use_iso = true;
  target.iso = 1.5;
  const TraceResult t = tracer.trace(0, Eigen::Vector4d(1, 0, 0, 0), target);  // from vertex (0, 0)
  ASSERT_EQ(t.status, TraceStatus::Reached) << to_string(t.status);
  EXPECT_LE((t.end - Eigen::Vector3d(0.75, 0.75, 0)).norm(), 1e-12);

  // Curved: the unit sphere with u = z (harmonic field with Dirichlet at the poles' caps):
  // traces from the equator go up the meridians to a marked ring of edges.
  const auto s = param_test::icosphere(4);
  const auto K = tri_cotan_laplacian(s.V, s.F);
  std::vector<int> north, south;
  for (Eigen::Index i = 0; i < s.V.rows(); ++i) {
    if (s.V(i, 2) > 0.95) north.push_back(static_cast<int>(i));
    if (s.V(i, 2) < -0.95) south.push_back(static_cast<int>(i));
  }
  const Eigen::VectorXd f = harmonic_field(K, {{north, 1.0}, {south, -1.0}});
  const TetTopology stopo = build_tet_topology(s.F, s.V.rows());
  const GradientTracer st(s.V, s.F, stopo, f);
  TraceTarget iso;
  iso.use_iso = true;
  iso.iso = 0.9;
  int n_reached = 0;
  for (Eigen::Index c = 0; c < s.F.rows(); c += 97) {
    // Not from inside the caps, where the field is constant (no gradient to follow).
    if (std::abs(s.V(s.F(c, 0), 2)) > 0.9) continue;
    const TraceResult r = st.trace(static_cast<int>(c), Eigen::Vector4d(0.2, 0.3, 0.5, 0), iso);
    ASSERT_EQ(r.status, TraceStatus::Reached) << "from face " << c << ": " << to_string(r.status) << " end " << r.end.transpose() << " value " << r.value << " cell " << r.cell << " bary " << r.bary.transpose() << " steps " << r.steps << " path " << r.path.rows() << " start " << r.path.row(0);
    ++n_reached;
    EXPECT_NEAR(r.value, 0.9, 1e-12);
    EXPECT_GT(r.end.z(), 0.5);
    // Every path point lies on the surface mesh: |p| <= 1 and close to 1.
    for (Eigen::Index k = 0; k < r.path.rows(); ++k) EXPECT_NEAR(r.path.row(k).norm(), 1.0, 3e-3);
    // Along a meridian: the azimuth barely changes.
    const Eigen::Vector3d a = r.path.row(0), b = r.end;
    if (std::hypot(a.x(), a.y()) > 0.3)
      EXPECT_LT(std::abs(std::remainder(std::atan2(a.y(), a.x()) - std::atan2(b.y(), b.x()), 2 * M_PI)), 0.1);
  }
  EXPECT_GT(n_reached, 20);
}
