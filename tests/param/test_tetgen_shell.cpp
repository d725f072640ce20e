// The shell again, now tetrahedralized by TetGen (mesh::tetrahedralize on two
// icospheres): an unstructured mesh, the kind later stages get, for the maximum
// principle and for tracing.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "igaprep/mesh/tetrahedralize.h"
#include "igaprep/param/harmonic_field.h"
#include "igaprep/param/maximum_principle.h"
#include "igaprep/param/stiffness_matrix.h"
#include "igaprep/param/tet_topology.h"
#include "igaprep/param/trace_gradient.h"
#include "param_meshes.h"

using namespace igaprep::param;

TEST(TetgenShell, NoExtremaAndTracesReachTheInnerSphere) {
  auto outer = param_test::icosphere(3);
  outer.V *= 2.0;
  const auto inner = param_test::icosphere(5);  // flat triangles within 2e-4 of r = 1
  igaprep::mesh::TetgenOptions opt;
  opt.max_volume = 0.002;
  const auto full = igaprep::mesh::tetrahedralize({outer, inner}, {}, opt);
  // Keep material 0 (between the spheres), renumbering the vertices it uses.
  std::vector<int> map(full.V.rows(), -1), keep;
  int nv = 0;
  for (Eigen::Index t = 0; t < full.T.rows(); ++t)
    if (full.material(t) == 0) {
      keep.push_back(static_cast<int>(t));
      for (int k = 0; k < 4; ++k)
        if (map[full.T(t, k)] < 0) map[full.T(t, k)] = nv++;
    }
  Eigen::MatrixXd V(nv, 3);
  Eigen::MatrixXi T(static_cast<Eigen::Index>(keep.size()), 4);
  for (Eigen::Index i = 0; i < full.V.rows(); ++i)
    if (map[i] >= 0) V.row(map[i]) = full.V.row(i);
  for (size_t j = 0; j < keep.size(); ++j)
    for (int k = 0; k < 4; ++k) T(static_cast<Eigen::Index>(j), k) = map[full.T(keep[j], k)];
  std::vector<int> in, out;
  std::vector<char> dir(nv, 0);
  for (int i = 0; i < nv; ++i) {
    const double r = V.row(i).norm();
    if (std::abs(r - 1) < 1e-9) in.push_back(i), dir[i] = 1;
    if (std::abs(r - 2) < 1e-9) out.push_back(i), dir[i] = 1;
  }
  ASSERT_EQ(in.size(), static_cast<size_t>(inner.V.rows()));
  ASSERT_EQ(out.size(), static_cast<size_t>(outer.V.rows()));
  std::vector<Eigen::RowVector3i> inner_faces;
  for (Eigen::Index f = 0; f < full.F.rows(); ++f)
    if (full.F_marker(f) == 1)
      inner_faces.emplace_back(map[full.F(f, 0)], map[full.F(f, 1)], map[full.F(f, 2)]);
  Eigen::MatrixXi IF(static_cast<Eigen::Index>(inner_faces.size()), 3);
  for (size_t f = 0; f < inner_faces.size(); ++f) IF.row(static_cast<Eigen::Index>(f)) = inner_faces[f];

  const auto K = tet_stiffness(V, T);
  const Eigen::VectorXd u = harmonic_field(K, {{in, 1.0}, {out, 0.0}});
  EXPECT_EQ(find_interior_extrema(K, u, dir).size(), 0u);

  const TetTopology topo = build_tet_topology(T, nv);
  TraceTarget target;
  target.marked = mark_facets(T, topo, IF);
  const GradientTracer tracer(V, T, topo, u);
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> U(-1.0, 1.0), R(1.02, 1.98);
  double drift = 0.0, worst = 0.0, angle_sum = 0.0, length_sum = 0.0;
  int hint = 0;
  for (int i = 0; i < 500; ++i) {
    Eigen::Vector3d d;
    do d = Eigen::Vector3d(U(rng), U(rng), U(rng));
    while (d.norm() > 1.0 || d.norm() < 0.1);
    const Eigen::Vector3d p = R(rng) * d.normalized();
    Eigen::Vector4d b;
    hint = tracer.locate(p, hint, &b);
    ASSERT_GE(hint, 0);
    const TraceResult t = tracer.trace(hint, b, target);
    ASSERT_EQ(t.status, TraceStatus::Reached) << i << ": " << to_string(t.status);
    worst = std::max(worst, std::abs(t.end.norm() - 1.0));
    drift += std::acos(std::clamp(p.normalized().dot(t.end.normalized()), -1.0, 1.0)) * 180 / M_PI;
    for (Eigen::Index k = 0; k + 1 < t.path.rows(); ++k) {
      const Eigen::Vector3d a = t.path.row(k), c = t.path.row(k + 1);
      const double len = (c - a).norm();
      angle_sum += len * std::acos(std::clamp((c - a).normalized().dot(-(a + c).normalized()), -1.0, 1.0)) * 180 / M_PI;
      length_sum += len;
    }
  }
  std::printf("TetGen shell (%ld tets): mean drift %.3f deg, mean segment deviation %.3f deg, worst |r - 1| %.2e\n",
              static_cast<long>(T.rows()), drift / 500, angle_sum / length_sum, worst);
  EXPECT_LT(worst, 1e-3);
  EXPECT_LT(drift / 500, 2.0);  // start and end directions: the trace stays on its ray
  // Per segment the piecewise-constant gradient of an unstructured mesh wobbles
  // by a few degrees (0.4 degrees on the structured shell, test_trace.cpp).
  EXPECT_LT(angle_sum / length_sum, 5.0);
}
