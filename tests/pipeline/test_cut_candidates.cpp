// The automatic cut keeps the valid candidate with the shortest paths to
// M0 (seed paper, section 4.1), on a real shape from ../shared/models.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "igaprep/param/polycube_2d.h"
#include "igaprep/pipeline/case.h"
#include "igaprep/pipeline/midsurface.h"
#include "igaprep/pipeline/surfaces.h"

namespace {

// The hand is a cupped plate 0.26 thick across its palm: the palm plane
// misses the thumb and the little finger (they lie above it). The cut
// between its two sides gives M0 through all five fingers, each an arm of
// the (u, v) domain; its paths to M0 are a third of the thickness long on
// average, good enough to stop there. (Before 2026-12-07 the thin sides'
// M0 was refused for one loop edge in three triangles, and the palm plane
// was kept: fidelity 13.2 % against 1.2 % now.)
TEST(CutCandidates, TheHandIsCutBetweenItsSidesWithAnArmPerFinger) {
  const std::string obj = std::string(IGAPREP_SHARED_MODELS_DIR) + "/hand.obj";
  if (!std::filesystem::exists(obj)) GTEST_SKIP() << "shared model " << obj << " is absent";
  const igaprep::pipeline::Case c =
      igaprep::pipeline::parse_case("{\"surfaces\": [\"" + obj + "\"]}", ".", "hand test case");
  igaprep::pipeline::Observer quiet;
  const igaprep::pipeline::Surfaces s = igaprep::pipeline::load_surfaces(c);
  const auto mid = igaprep::pipeline::midsurface_stage(c, s, quiet);
  ASSERT_EQ(mid.valid.size(), 1u);
  EXPECT_NE(mid.cut.source.find("thin sides"), std::string::npos) << mid.cut.source;
  EXPECT_FALSE(mid.second_best);
  EXPECT_GT(mid.paths.mean, 0.03);  // measured 0.043
  EXPECT_LT(mid.paths.mean, 0.06);
  EXPECT_EQ(mid.polycube.domain.arms.size(), 5u);
  EXPECT_GT(mid.polycube.min_jacobian, 0.0);
  EXPECT_LT(igaprep::param::squeezed_share(mid.m0trim.mesh, mid.polycube.jacobian), 0.01);  // measured 0.09 %
  // M0 reaches the thumb's tip (x -0.40), the little finger's (x 0.30) and the middle finger's (y 0.93).
  const Eigen::Vector3d lo = mid.m0.mesh.V.colwise().minCoeff(), hi = mid.m0.mesh.V.colwise().maxCoeff();
  EXPECT_LT(lo.x(), -0.37);
  EXPECT_GT(hi.x(), 0.27);
  EXPECT_GT(hi.y(), 0.90);
}

// The kitten's first principal plane gives a (u, v) map that folds next to
// its hole's corners and is made bijective only with cuts from them (a
// pinwheel of small rectangles: 143 negative elements downstream); the same
// plane moved off the centre gives a map without them, and is the one kept,
// though its paths to M0 are 1 % longer.
TEST(CutCandidates, TheKittensCutNeedsNoCutsFromItsHolesCorners) {
  const std::string obj = std::string(IGAPREP_SHARED_MODELS_DIR) + "/kitten.obj";
  if (!std::filesystem::exists(obj)) GTEST_SKIP() << "shared model " << obj << " is absent";
  const igaprep::pipeline::Case c =
      igaprep::pipeline::parse_case("{\"surfaces\": [\"" + obj + "\"]}", ".", "kitten test case");
  igaprep::pipeline::Observer quiet;
  const igaprep::pipeline::Surfaces s = igaprep::pipeline::load_surfaces(c);
  const auto mid = igaprep::pipeline::midsurface_stage(c, s, quiet);
  ASSERT_EQ(mid.valid.size(), 2u);
  EXPECT_NE(mid.valid[0].find("with cuts from the holes' corners"), std::string::npos) << mid.valid[0];
  EXPECT_EQ(mid.valid[1].find("with cuts from the holes' corners"), std::string::npos) << mid.valid[1];
  EXPECT_NE(mid.valid[1].find(mid.cut.source), std::string::npos) << mid.cut.source;
  EXPECT_TRUE(mid.polycube.hole_cuts.empty());
  EXPECT_GT(mid.polycube.min_jacobian, 0.0);
  EXPECT_EQ(mid.m0trim.boundary_loops.size(), 2u);
}

}  // namespace
