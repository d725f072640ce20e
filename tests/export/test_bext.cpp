// BEXT: an independent reader rebuilds each element's Bernstein points from
// the file (C^T times the global nodes) and gets our Bezier extraction back.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <map>
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
  // Issue 23, item 1: each distinct coefficient vector once (per block of
  // patches with the same degrees), not one per element and function.
  // Vectors equal to round-off are merged: between the exact count and the
  // count of vectors distinct beyond 1e-10.
  std::map<std::array<int, 3>, std::set<std::vector<double>>> distinct;
  std::map<std::array<int, 3>, std::set<std::vector<long long>>> distinct_beyond;
  long long per_element = 0;
  for (const auto& p : mp.patches) {
    const auto ex = igaprep::spline::bezier_extraction(p);
    for (int ew = 0; ew < ex.element_count(2); ++ew)
      for (int ev = 0; ev < ex.element_count(1); ++ev)
        for (int eu = 0; eu < ex.element_count(0); ++eu) {
          const Eigen::MatrixXd C = igaprep::spline::element_extraction_operator(ex, eu, ev, ew);
          for (Eigen::Index r = 0; r < C.rows(); ++r) {
            std::vector<double> row;
            std::vector<long long> coarse;
            for (Eigen::Index c = 0; c < C.cols(); ++c) {
              row.push_back(C(r, c));
              coarse.push_back(std::llround(C(r, c) * 1e10));
            }
            distinct[p.degrees].insert(row);
            distinct_beyond[p.degrees].insert(coarse);
            ++per_element;
          }
        }
  }
  long long exact = 0, beyond = 0;
  for (const auto& [degrees, rows] : distinct) exact += static_cast<long long>(rows.size());
  for (const auto& [degrees, rows] : distinct_beyond) beyond += static_cast<long long>(rows.size());
  EXPECT_LE(j["vectors"].get<long long>(), exact);
  EXPECT_GE(j["vectors"].get<long long>(), beyond);
  EXPECT_LT(2 * exact, per_element);
  EXPECT_LT(worst, 1e-13);
  EXPECT_LT(worst_w, 1e-13);
  std::filesystem::remove_all(dir);
}

}  // namespace
