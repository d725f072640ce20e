// Paths along -grad w from M's corners and boundary vertices out to T1 (seed
// paper, sections 5.1 and 5.2): the spines of the corner surfaces and of S+
// and S-.
#include <gtest/gtest.h>

#include <cmath>

#include "decomposition_cache.h"
#include "igaprep/param/boundary_traces.h"

using namespace igaprep::param;

namespace {
class TracesTest : public ::testing::TestWithParam<std::string> {};

// Monotone and ending on T1, checked with geometry computed here.
void check_trace(const BoundaryTrace& bt, const igaprep::mesh::TriMesh& T1, const igaprep::mesh::TriMesh& T2,
                 double diag, const std::string& what) {
  ASSERT_EQ(bt.trace.status, TraceStatus::Reached) << what << ": " << to_string(bt.trace.status);
  const Eigen::Vector3d end = bt.trace.path.bottomRows(1).transpose();
  EXPECT_LT(midsurface_test::distance_to_surface(end, T1), 1e-9 * diag) << what;
  ASSERT_EQ(bt.w.size(), bt.trace.path.rows());
  EXPECT_NEAR(bt.w(bt.w.size() - 1), 0.0, 1e-9) << what;
  double rise = 0.0;
  for (Eigen::Index i = 0; i + 1 < bt.w.size(); ++i) rise = std::max(rise, bt.w(i + 1) - bt.w(i));
  EXPECT_LE(rise, 1e-12) << what;
  EXPECT_EQ(rise, bt.max_rise) << what;
  // It starts inside T2 and ends outside: it passed through T2.
  const Eigen::Vector3d start = bt.trace.path.row(0).transpose();
  EXPECT_GT(midsurface_test::winding_number(start, T2), 0.5) << what;
  EXPECT_LT(midsurface_test::winding_number(end, T2), 0.5) << what;
}
}  // namespace

TEST_P(TracesTest, CornerAndBoundaryTracesReachT1) {
  const auto& c = decomposition_test::cached(GetParam());
  const auto& model = c.mid->model;
  const auto& M = c.mid->result.base;
  const auto& T1 = model.surfaces[0];
  const auto& T2 = model.surfaces[1];
  BoundaryTraceOptions opt;
  opt.side_offset = 1e-3;
  const BoundaryTraces bt = trace_boundaries(c.H, c.w, M, opt);

  ASSERT_EQ(bt.corners.size(), M.corners.size());
  ASSERT_EQ(bt.loops.size(), M.boundary_loops.size());
  int corner_count = 0;
  for (std::size_t l = 0; l < bt.corners.size(); ++l)
    for (int k = 0; k < 4; ++k) {
      const BoundaryTrace& t = bt.corners[l][static_cast<std::size_t>(k)];
      EXPECT_EQ(t.vertex, M.corners[l][static_cast<std::size_t>(k)]);
      // Starts exactly on the corner, where w = 1.
      EXPECT_EQ((t.trace.path.row(0) - M.mesh.V.row(t.vertex)).norm(), 0.0);
      EXPECT_NEAR(t.w(0), 1.0, 1e-12);
      check_trace(t, T1, T2, c.mid->diag, "corner " + std::to_string(l) + "." + std::to_string(k));
      ++corner_count;
    }

  // Every boundary vertex of M, and the side starts p +- e n.
  auto summary = [&](const std::vector<std::vector<BoundaryTrace>>& set, const char* name) {
    int total = 0, reached = 0;
    for (std::size_t l = 0; l < set.size(); ++l)
      for (std::size_t i = 0; i < set[l].size(); ++i) {
        ++total;
        if (set[l][i].trace.status != TraceStatus::Reached) {
          std::printf("  %s loop %zu vertex %d: %s\n", name, l, set[l][i].vertex, to_string(set[l][i].trace.status));
          continue;
        }
        ++reached;
        check_trace(set[l][i], T1, T2, c.mid->diag, std::string(name) + " loop " + std::to_string(l));
      }
    std::printf("%s %s: %d of %d traces reach T1\n", GetParam().c_str(), name, reached, total);
    return std::make_pair(reached, total);
  };
  const auto on = summary(bt.loops, "boundary");
  const auto plus = summary(bt.plus, "side +");
  const auto minus = summary(bt.minus, "side -");
  std::printf("%s: %d corner traces, %d of %d traces reach T1 (%d stalled traces resumed; still stalled %d, "
              "hit boundary %d, budget %d)\n",
              GetParam().c_str(), corner_count, bt.reached, bt.total, bt.resumed,
              bt.status_count[static_cast<int>(TraceStatus::Stalled)],
              bt.status_count[static_cast<int>(TraceStatus::HitBoundary)],
              bt.status_count[static_cast<int>(TraceStatus::StepBudget)]);
  EXPECT_EQ(on.first, on.second);
  EXPECT_EQ(plus.first, plus.second);
  EXPECT_EQ(minus.first, minus.second);
  EXPECT_EQ(bt.reached, bt.total);
  int boundary_vertices = 0;
  for (const auto& l : M.boundary_loops) boundary_vertices += static_cast<int>(l.size());
  EXPECT_EQ(bt.total, 3 * boundary_vertices + corner_count);
}

INSTANTIATE_TEST_SUITE_P(Models, TracesTest, ::testing::Values("sphere2", "ring2"),
                         [](const auto& info) { return info.param; });
