// BEXT: an independent reader rebuilds each element's Bernstein points from
// the file (C^T times the global nodes) and gets our Bezier extraction back.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>

#include "igaprep/export/bext.h"
#include "igaprep/spline/bezier_extraction.h"
#include "igaprep/spline/multipatch_topology.h"
#include "test_model.h"
#include "test_util.h"

namespace {
using namespace igaprep::test;

TEST(Bext, ReaderRebuildsOurBernsteinPoints) {
  const std::string dir = scratch_dir("bext");
  const igaprep::spline::MultiPatch mp = make_test_model();
  igaprep::exporter::write_bext(mp, dir + "/m.bext");
  const CommandResult r = run_python("read_bext.py", {dir + "/m.bext"});
  ASSERT_EQ(r.status, 0) << r.output.substr(0, 2000);
  const nlohmann::json j = nlohmann::json::parse(r.output);
  // Shared interface points are one node each.
  EXPECT_EQ(j["nodes"].get<int>(), igaprep::spline::global_numbering(mp).count);
  int total = 0;
  for (const auto& p : mp.patches) total += igaprep::spline::bezier_extraction(p).element_count();
  ASSERT_EQ(static_cast<int>(j["elements"].size()), total);
  double worst = 0.0, worst_w = 0.0;
  std::set<std::array<int, 4>> seen;
  for (const auto& e : j["elements"]) {
    const int p = e["patch"].get<int>();
    const int eu = e["element"][0], ev = e["element"][1], ew = e["element"][2];
    seen.insert({p, eu, ev, ew});
    const auto& patch = mp.patches[p];
    for (int d = 0; d < 3; ++d) EXPECT_EQ(e["degrees"][d].get<int>(), patch.degrees[d]);
    const auto ex = igaprep::spline::bezier_extraction(patch);
    const auto be = igaprep::spline::bernstein_control_points(patch, ex, eu, ev, ew);
    ASSERT_EQ(static_cast<Eigen::Index>(e["points"].size()), be.points.rows());
    for (Eigen::Index b = 0; b < be.points.rows(); ++b) {
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(e["points"][b][c].get<double>() - be.points(b, c)));
      const double w = patch.rational() ? be.weights[b] : 1.0;
      worst_w = std::max(worst_w, std::abs(e["weights"][b].get<double>() - w));
    }
  }
  EXPECT_EQ(static_cast<int>(seen.size()), total) << "every element exactly once";
  EXPECT_LT(worst, 1e-13);
  EXPECT_LT(worst_w, 1e-13);
  std::filesystem::remove_all(dir);
}

}  // namespace
