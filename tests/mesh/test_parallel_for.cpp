// core's parallel_for: every item runs once on any thread count, and the
// exception of the lowest failing item comes out after all have run.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "igaprep/core/parallel.h"

namespace {

TEST(ParallelFor, EveryItemOnceAndTheLowestFailureRethrown) {
  for (const int threads : {1, 2, 3}) {
    igaprep::set_thread_count(threads);
    std::vector<int> runs(1000, 0);
    igaprep::parallel_for(runs.size(), [&](std::size_t i) { runs[i] += static_cast<int>(i) + 1; });
    for (std::size_t i = 0; i < runs.size(); ++i) ASSERT_EQ(runs[i], static_cast<int>(i) + 1) << threads << " threads";
    std::vector<int> ran(100, 0);
    try {
      igaprep::parallel_for(ran.size(), [&](std::size_t i) {
        ran[i] = 1;
        if (i == 70 || i == 30) throw std::runtime_error("item " + std::to_string(i));
      });
      ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "item 30");
    }
    for (const int r : ran) EXPECT_EQ(r, 1);
  }
  igaprep::set_thread_count(0);
}

}  // namespace
