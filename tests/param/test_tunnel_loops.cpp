// Tunnel loops (loops round a solid's through-holes) and the cuts they give.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>

#include "igaprep/core/error.h"
#include "igaprep/mesh/offset_surface.h"
#include "igaprep/mesh/read_surface.h"
#include "igaprep/models/shapes.h"
#include "igaprep/param/midsurface_pipeline.h"
#include "igaprep/param/tunnel_loops.h"

using namespace igaprep;
using namespace igaprep::param;

namespace {

Eigen::MatrixXd circle(const Eigen::Vector3d& centre, const Eigen::Vector3d& e1, const Eigen::Vector3d& e2, int n) {
  Eigen::MatrixXd p(n, 3);
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * M_PI * i / n;
    p.row(i) = (centre + std::cos(t) * e1 + std::sin(t) * e2).transpose();
  }
  return p;
}

double radius_from_z_axis(const mesh::TriMesh& m, int v) { return m.V.row(v).head<2>().norm(); }

double loop_length(const mesh::TriMesh& m, const std::vector<int>& loop) {
  double sum = 0.0;
  for (std::size_t i = 0; i < loop.size(); ++i) sum += (m.V.row(loop[i]) - m.V.row(loop[(i + 1) % loop.size()])).norm();
  return sum;
}

}  // namespace

TEST(LinkingNumber, HopfLinkIsOneAndUnlinkedCirclesZero) {
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(), z = Eigen::Vector3d::UnitZ();
  const Eigen::MatrixXd a = circle(Eigen::Vector3d::Zero(), x, y, 40);
  const Eigen::MatrixXd linked = circle(x, x, z, 37);
  EXPECT_NEAR(std::abs(linking_number(a, linked)), 1.0, 1e-9);
  // Symmetric, and reversing one loop changes the sign.
  EXPECT_NEAR(linking_number(a, linked), linking_number(linked, a), 1e-9);
  EXPECT_NEAR(linking_number(a, linked.colwise().reverse()), -linking_number(a, linked), 1e-9);
  // The same circle moved clear of a: no link.
  EXPECT_NEAR(linking_number(a, circle(3.0 * x, x, z, 37)), 0.0, 1e-9);
  // Passing near a (0.01 from it) without going through: still none.
  EXPECT_NEAR(linking_number(a, circle(Eigen::Vector3d(2.01, 0, 0), x, z, 37)), 0.0, 1e-9);
}

// The meridians (round the tube, 2 pi 0.4 long) are the shortest loops but
// bound disks inside the solid; the tunnel loop is the inner equator.
TEST(TunnelLoops, TheTorusLoopIsItsInnerEquator) {
  const mesh::TriMesh torus = models::make_torus(1.0, 0.4, 48, 24);
  const auto loops = tunnel_loops(torus);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].size(), 48u);
  for (int v : loops[0]) {
    EXPECT_NEAR(radius_from_z_axis(torus, v), 0.6, 1e-9);
    EXPECT_NEAR(torus.V(v, 2), 0.0, 1e-9);
  }
}

// Three holes in a row: one loop round each hole's wall, apart from the others.
TEST(TunnelLoops, TheThreeHoleFrameGetsOneLoopRoundEachHole) {
  const mesh::TriMesh frame = models::make_three_hole_frame(0.15, 0.06);
  const auto loops = tunnel_loops(frame);
  ASSERT_EQ(loops.size(), 3u);
  std::set<int> seen;
  std::vector<double> centre_x;
  for (const auto& loop : loops) {
    for (int v : loop) EXPECT_TRUE(seen.insert(v).second) << "loops share vertex " << v;
    Eigen::RowVector3d c = Eigen::RowVector3d::Zero();
    for (int v : loop) c += frame.V.row(v);
    c /= static_cast<double>(loop.size());
    centre_x.push_back(c(0));
    // Round a hole (its wall 1 x 1.2 less the tube), not along the outline (3 x 1.2).
    EXPECT_LT(loop_length(frame, loop), 4.0);
  }
  // The holes' centres: x = -1, 0, 1.
  std::sort(centre_x.begin(), centre_x.end());
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(centre_x[static_cast<std::size_t>(i)], i - 1.0, 0.1);
}

// The loops depend on the surface, not on the order its triangles are
// listed in: the triangles reversed give the same loops, on the frame and
// on the hip bone.
std::set<std::set<int>> loop_sets(const std::vector<std::vector<int>>& loops) {
  std::set<std::set<int>> out;
  for (const auto& loop : loops) out.insert(std::set<int>(loop.begin(), loop.end()));
  return out;
}

void expect_same_loops_reversed(const mesh::TriMesh& m, std::size_t genus) {
  mesh::TriMesh reversed = m;
  reversed.F = m.F.colwise().reverse();
  const auto a = tunnel_loops(m), b = tunnel_loops(reversed);
  ASSERT_EQ(a.size(), genus);
  EXPECT_EQ(loop_sets(a), loop_sets(b));
}

TEST(TunnelLoops, TheFacesOrderDoesNotChangeTheLoops) {
  expect_same_loops_reversed(models::make_three_hole_frame(0.15, 0.06), 3);
  const std::string path = std::string(IGAPREP_SHARED_MODELS_DIR) + "/pelvis_hip.stl";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared model " << path << " is absent";
  expect_same_loops_reversed(mesh::read_surface(path), 2);
}

TEST(TunnelLoops, GenusZeroIsRefused) {
  EXPECT_THROW(tunnel_loops(models::make_ellipsoid(1.0, 0.8, 0.6, 3)), Error);
}

// The torus's one loop, with its two sides apart: the rim is the outer
// equator (by symmetry), with the harmonic field and with the tube's two
// sides pulled apart, and each cut is valid.
TEST(TunnelLoopCuts, TheTorusRimIsItsOuterEquator) {
  const mesh::TriMesh torus = models::make_torus(1.0, 0.4, 48, 24);
  std::vector<std::string> refusals;
  const auto cuts = tunnel_loop_cuts(torus, tunnel_loops(torus), "torus", refusals);
  ASSERT_EQ(cuts.size(), 2u) << (refusals.empty() ? "" : refusals.front());
  for (const CutLoops& cut : cuts) {
    ASSERT_EQ(cut.loops.size(), 2u);
    const int outer = radius_from_z_axis(cut.surface, cut.loops[0][0]) > 1.0 ? 0 : 1;
    for (int v : cut.loops[static_cast<std::size_t>(outer)]) {
      EXPECT_NEAR(radius_from_z_axis(cut.surface, v), 1.4, 0.02) << cut.source;
      EXPECT_NEAR(cut.surface.V(v, 2), 0.0, 0.05) << cut.source;
    }
    EXPECT_NE(cut.source.find("tunnel loops"), std::string::npos);
  }
}

// The frame's three loops with every choice of sides: the one with all holes'
// upper sides together is valid (4 loops: the holes and the outline).
TEST(TunnelLoopCuts, TheFrameWithItsHolesSidesAlikeIsValid) {
  const mesh::TriMesh frame = models::make_three_hole_frame(0.15, 0.06);
  std::vector<std::string> refusals;
  const auto cuts = tunnel_loop_cuts(frame, tunnel_loops(frame), "frame", refusals);
  ASSERT_FALSE(cuts.empty()) << (refusals.empty() ? "" : refusals.front());
  EXPECT_EQ(cuts.front().loops.size(), 4u);
  EXPECT_EQ(cuts.size() + refusals.size(), 8u);  // 2^(3-1) choices, harmonic and with the thin sides
}

// The hip bone of ../shared/models (genus 2: the obturator foramen and a
// small hole) with its 0.8 mm cortical shell, as its validation case: no
// plane cuts both holes, and the thin sides twist through the pubic rami;
// the tunnel loops give its automatic cut. Its (u, v) map folds next to the
// holes' corners and is made bijective by the cuts from them.
TEST(TunnelLoopCuts, ThePelvisGetsAnAutomaticCut) {
  const std::string path = std::string(IGAPREP_SHARED_MODELS_DIR) + "/pelvis_hip.stl";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared model " << path << " is absent";
  const mesh::TriMesh pelvis = mesh::read_surface(path);
  const mesh::TriMesh trabecular = mesh::offset_inward(pelvis, {0.8});
  const MidsurfaceResult r = build_midsurface({pelvis, trabecular}, MidsurfaceOptions{}, "pelvis");
  EXPECT_NE(r.cut.source.find("tunnel loops"), std::string::npos) << r.cut.source;
  EXPECT_NE(r.cut.source.find("thin parts"), std::string::npos) << r.cut.source;
  EXPECT_EQ(r.cut.loops.size(), 3u);
  EXPECT_EQ(r.m0trim.boundary_loops.size(), 3u);
  // Paths from T1 to M0 of a bone 1.6 to 25 mm thick: 4.7 mm on average.
  EXPECT_LT(r.paths.mean, 6.0);
  EXPECT_EQ(r.polycube.hole_cuts.size(), 8u);
  EXPECT_GT(r.polycube.min_jacobian, 0.0);
}
