// Quality metrics against closed forms; fidelity and volumes of an exact
// NURBS sphere shell against triangulated spheres.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "check/check_models.h"
#include "igaprep/iga_check/fidelity.h"
#include "igaprep/iga_check/jacobian_certificate.h"
#include "igaprep/iga_check/quality_metrics.h"
#include "igaprep/iga_check/topology_checks.h"
#include "igaprep/mesh/enclosed_volume.h"
#include "igaprep/spline/refine.h"

using namespace igaprep;
using namespace igaprep::iga_check;

TEST(QualityMetrics, AffineBoxHasScaledJacobianOne) {
  auto box = [](const Eigen::Vector3d& t) { return Eigen::Vector3d(2.0 * t[0] + 1, 3.0 * t[1], 0.5 * t[2] - 4); };
  const auto mp = check_test::single(spline::refine_uniformly(check_test::bezier_patch(box, {{2, 2, 2}}), 1));
  const QualityReport q = quality_metrics(mp);
  ASSERT_EQ(q.patches.size(), 1u);
  const PatchQuality& pq = q.patches[0];
  EXPECT_EQ(pq.points, std::pow(2 * (5 + 3), 3));  // 2 elements x (5 grid + 3 Gauss) per direction
  EXPECT_NEAR(pq.scaled_jacobian.min, 1.0, 1e-12);
  EXPECT_NEAR(pq.scaled_jacobian.max, 1.0, 1e-12);
  EXPECT_NEAR(pq.det_j.min, 3.0, 1e-12);
  EXPECT_NEAR(pq.det_j.max, 3.0, 1e-12);
  const double cond = std::sqrt(4 + 9 + 0.25) * std::sqrt(0.25 + 1.0 / 9 + 4) / 3;
  EXPECT_NEAR(pq.condition.mean, cond, 1e-12);
  EXPECT_EQ(pq.scaled_jacobian.histogram.counts.back(), pq.points);  // all in the last bin, [0.9, 1]
}

TEST(QualityMetrics, ShearedBoxMatchesClosedForm) {
  const double a = 2.0, b = 1.5, c = 0.7, s = 0.9;
  auto shear = [=](const Eigen::Vector3d& t) { return Eigen::Vector3d(a * t[0] + s * t[1], b * t[1], c * t[2]); };
  const auto mp = check_test::single(check_test::bezier_patch(shear, {{1, 1, 1}}));
  const QualityReport q = quality_metrics(mp);
  const double sj = b / std::sqrt(s * s + b * b);
  const double cond = std::sqrt(a * a + s * s + b * b + c * c) *
                      std::sqrt(1 / (a * a) + s * s / (a * a * b * b) + 1 / (b * b) + 1 / (c * c)) / 3;
  EXPECT_NEAR(q.overall.scaled_jacobian.min, sj, 1e-12);
  EXPECT_NEAR(q.overall.scaled_jacobian.max, sj, 1e-12);
  EXPECT_NEAR(q.overall.condition.min, cond, 1e-12);
  EXPECT_NEAR(q.overall.condition.max, cond, 1e-12);
  EXPECT_NEAR(q.overall.det_j.mean, a * b * c, 1e-12);
  EXPECT_NEAR(scaled_jacobian(Eigen::Matrix3d::Identity()), 1.0, 1e-15);
  Eigen::Matrix3d singular = Eigen::Matrix3d::Identity();
  singular(2, 2) = 0.0;
  EXPECT_TRUE(std::isinf(condition_number(singular)));
}

TEST(QualityMetrics, WorstPointsAreTheSmallestScaledJacobian) {
  auto fold = [](const Eigen::Vector3d& t) { return Eigen::Vector3d(t[0] + 3.0 * t[0] * (1 - t[0]) * t[1], t[1], t[2]); };
  const auto mp = check_test::single(spline::refine_uniformly(check_test::bezier_patch(fold, {{2, 2, 2}}), 1));
  QualityOptions opt;
  opt.worst_count = 3;
  const QualityReport q = quality_metrics(mp, opt);
  ASSERT_EQ(q.worst.size(), 3u);
  EXPECT_DOUBLE_EQ(q.worst[0].scaled_jacobian, q.overall.scaled_jacobian.min);
  EXPECT_LE(q.worst[0].scaled_jacobian, q.worst[1].scaled_jacobian);
  EXPECT_LT(q.worst[0].det_j, 0.0);
  // The fold: det J = 1 + 3 (1 - 2u) v, most negative at u = v = 1.
  EXPECT_NEAR(q.overall.det_j.min, -2.0, 1e-9);
  EXPECT_NEAR(q.worst[0].uvw[0], 1.0, 1e-12);
  EXPECT_EQ(q.worst[0].element[0], 1);
}

namespace {

// Largest distance from the sphere of radius r to an inscribed triangle mesh:
// the sagitta over the triangle whose plane is closest to the centre.
double max_sagitta(const mesh::TriMesh& m, double r) {
  double best = 0.0;
  for (int f = 0; f < m.F.rows(); ++f) {
    const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
    best = std::max(best, r - std::abs(n.dot(a)));
  }
  return best;
}

}  // namespace

TEST(Fidelity, SphereShellMatchesChordError) {
  const double r0 = 0.5, r1 = 1.0;
  const auto mp = check_test::sphere_shell(r0, r1);
  const std::vector<mesh::TriMesh> surfaces = {check_test::icosphere(r1, 3), check_test::icosphere(r0, 3)};
  FidelityOptions opt;
  opt.samples_per_element = 60;
  const double diag = model_diagonal(mp);
  EXPECT_NEAR(diag, 2.0 * std::sqrt(3.0), 1e-9);  // the box [-1, 1]^3
  const auto fid = fidelity(mp, surfaces, diag, opt);
  ASSERT_EQ(fid.size(), 2u);
  for (int s = 0; s < 2; ++s) {
    const double r = s == 0 ? r1 : r0;
    const SurfaceFidelity& f = fid[s];
    EXPECT_EQ(f.surface, s);
    EXPECT_EQ(f.boundary_faces, 4);
    const double sag = max_sagitta(surfaces[s], r);
    ASSERT_GT(sag, 2e-3 * r);  // the chord error is what the test resolves
    EXPECT_NEAR(f.spline_to_mesh.max, sag, 1e-3 * r);
    EXPECT_NEAR(f.spline_to_mesh.max, sag, 1e-4 * r);
    EXPECT_LE(f.spline_to_mesh.max, sag * (1 + 1e-9));
    EXPECT_NEAR(std::abs(f.spline_to_mesh.max_location.norm() - r), 0.0, 1e-9);
    EXPECT_LE(f.spline_to_mesh.p95, f.spline_to_mesh.max);
    EXPECT_LE(f.spline_to_mesh.mean, f.spline_to_mesh.p95);
    EXPECT_NEAR(f.spline_to_mesh.max_relative, f.spline_to_mesh.max / diag, 1e-15);
    // Mesh vertices lie on the exact sphere: distance zero up to the projection.
    EXPECT_EQ(f.mesh_to_spline.samples, surfaces[s].V.rows());
    EXPECT_LT(f.mesh_to_spline.max, 1e-8 * r);
  }
}

TEST(Topology, SphereShellWatertightVolumesAndCertificate) {
  const double r0 = 0.5, r1 = 1.0;
  const auto mp = check_test::sphere_shell(r0, r1);
  const std::vector<mesh::TriMesh> surfaces = {check_test::icosphere(r1, 4), check_test::icosphere(r0, 4)};
  const TopologyReport t = topology_checks(mp, surfaces);
  EXPECT_TRUE(t.conforming);
  EXPECT_LT(t.interface_max_gap, 1e-14);
  EXPECT_TRUE(t.watertight) << (t.watertight_problems.empty() ? "" : t.watertight_problems[0]);
  int collapsed = 0;
  for (const auto& s : t.sides) collapsed += s.kind == "collapsed";
  EXPECT_EQ(collapsed, 8);  // the poles
  const double exact = 4.0 / 3.0 * M_PI * (r1 * r1 * r1 - r0 * r0 * r0);
  ASSERT_EQ(t.material_volumes.size(), 1u);
  EXPECT_NEAR(t.material_volumes[0], exact, 1e-6 * exact);
  ASSERT_EQ(t.regions.size(), 2u);
  EXPECT_EQ(t.regions[0].patches, 4);
  EXPECT_EQ(t.regions[1].patches, 0);  // the void inside
  EXPECT_NEAR(t.regions[0].spline_volume, exact, 1e-6 * exact);
  // The inscribed meshes enclose a little less: chord error of level 4, < 0.5 %.
  EXPECT_GT(t.regions[0].relative_difference, 0.0);
  EXPECT_LT(t.regions[0].relative_difference, 5e-3);
  EXPECT_NEAR(std::abs(mesh::enclosed_volume(surfaces[0])), 4.0 / 3.0 * M_PI, 1e-2);

  // A side left out breaks watertightness and is named.
  auto broken = mp;
  broken.boundaries.pop_back();
  const TopologyReport tb = topology_checks(broken, {});
  EXPECT_FALSE(tb.watertight);
  ASSERT_EQ(tb.watertight_problems.size(), 1u);
  EXPECT_NE(tb.watertight_problems[0].find("patch 3 side 6"), std::string::npos);

  // The poles make the elements that touch them degenerate, never negative.
  const auto certs = certify_model(mp);
  int degenerate = 0;
  for (const auto& c : certs) {
    EXPECT_TRUE(c.status == ElementStatus::Positive || c.status == ElementStatus::Degenerate) << to_string(c.status);
    degenerate += c.status == ElementStatus::Degenerate;
  }
  EXPECT_EQ(degenerate, 8);
}

TEST(Fidelity, MaterialInterfaceOfTwoShells) {
  // Two shells: patches 0-3 between radii 0.5 and 0.75 (material 1), patches
  // 4-7 between 0.75 and 1 (material 0); their common sphere is label 1.
  auto inner = check_test::sphere_shell(0.5, 0.75);
  auto outer = check_test::sphere_shell(0.75, 1.0);
  spline::MultiPatch mp = outer;
  mp.boundaries.clear();
  mp.patches.insert(mp.patches.end(), inner.patches.begin(), inner.patches.end());
  for (int q = 0; q < 4; ++q) {
    mp.patches[4 + q].material = 1;
    spline::Interface itf = inner.interfaces[q];
    itf.patch_a += 4;
    itf.patch_b += 4;
    mp.interfaces.push_back(itf);
    spline::Interface radial;
    radial.patch_a = q;
    radial.side_a = spline::kW0;
    radial.patch_b = 4 + q;
    radial.side_b = spline::kW1;
    radial.surface = 1;
    mp.interfaces.push_back(radial);
    mp.boundaries.push_back({q, spline::kW1, 0});
    mp.boundaries.push_back({4 + q, spline::kW0, 2});
  }
  mp.labels = {"outer", "middle", "inner"};
  mp.materials = {{"outer", 1.0, 0.3}, {"inner", 1.0, 0.3}};
  const std::vector<mesh::TriMesh> surfaces = {check_test::icosphere(1.0, 3), check_test::icosphere(0.75, 3),
                                               check_test::icosphere(0.5, 3)};
  FidelityOptions opt;
  opt.samples_per_element = 60;
  const auto fid = fidelity(mp, surfaces, 0.0, opt);
  ASSERT_EQ(fid.size(), 3u);
  EXPECT_EQ(fid[1].interface_faces, 4);
  EXPECT_EQ(fid[1].boundary_faces, 0);
  EXPECT_NEAR(fid[1].spline_to_mesh.max, max_sagitta(surfaces[1], 0.75), 1e-4 * 0.75);
  EXPECT_LT(fid[1].mesh_to_spline.max, 1e-8);

  const TopologyReport t = topology_checks(mp, surfaces);
  EXPECT_TRUE(t.conforming) << (t.conformity_problems.empty() ? "" : t.conformity_problems[0]);
  EXPECT_TRUE(t.watertight) << (t.watertight_problems.empty() ? "" : t.watertight_problems[0]);
  ASSERT_EQ(t.regions.size(), 3u);
  EXPECT_EQ(t.regions[0].patches, 4);
  EXPECT_EQ(t.regions[1].patches, 4);
  EXPECT_EQ(t.regions[2].patches, 0);
  const double v0 = 4.0 / 3.0 * M_PI * (1.0 - 0.421875), v1 = 4.0 / 3.0 * M_PI * (0.421875 - 0.125);
  ASSERT_EQ(t.material_volumes.size(), 2u);
  EXPECT_NEAR(t.material_volumes[0], v0, 1e-6 * v0);
  EXPECT_NEAR(t.material_volumes[1], v1, 1e-6 * v1);
  EXPECT_NEAR(t.regions[1].spline_volume, v1, 1e-6 * v1);
}
