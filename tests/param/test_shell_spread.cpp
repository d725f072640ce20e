// Spreading a shell face's streamline ends evenly (param/shell_spread.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "igaprep/core/parallel.h"
#include "igaprep/param/shell_spread.h"

namespace {

using igaprep::param::even_end_params;
using igaprep::param::spread_face_params;

std::vector<double> uniform(int m) {
  std::vector<double> p(static_cast<std::size_t>(m));
  for (int i = 0; i < m; ++i) p[static_cast<std::size_t>(i)] = static_cast<double>(i) / (m - 1);
  return p;
}

// Ends bunched at s = 0 as in a fan (x = s^8: the last gap is half the
// curve) come out evenly spaced, to a tenth of the even gap.
TEST(EvenEndParams, BunchedEndsComeOutEvenlySpaced) {
  const std::vector<double> p = uniform(13);
  auto end = [](double s) { return Eigen::Vector3d(std::pow(s, 8), 0.0, 0.0); };
  std::vector<Eigen::Vector3d> ends;
  for (double s : p) ends.push_back(end(s));
  const std::vector<double> q = even_end_params(end, p, ends);
  ASSERT_EQ(q.size(), p.size());
  EXPECT_EQ(q.front(), 0.0);
  EXPECT_EQ(q.back(), 1.0);
  for (std::size_t i = 0; i < q.size(); ++i) EXPECT_NEAR(end(q[i]).x(), p[i], 0.1 / 12) << i;
  for (std::size_t i = 1; i < q.size(); ++i) EXPECT_GT(q[i], q[i - 1]);
}

// Ends whose largest gap is within 3 times the mean stay where they are
// (x = s^2: largest gap 23/144 against the mean 1/12).
TEST(EvenEndParams, EndsThatAreNotUnevenKeepTheirParameters) {
  const std::vector<double> p = uniform(13);
  auto end = [](double s) { return Eigen::Vector3d(s * s, 0.0, 0.0); };
  std::vector<Eigen::Vector3d> ends;
  for (double s : p) ends.push_back(end(s));
  EXPECT_EQ(even_end_params(end, p, ends), p);
}

// Ends evenly spaced along a line with a narrow bump between two of them
// (a Gaussian of height 0.05 and width 0.01 centred between samples 6 and
// 7): not uneven, so they stay; with chord_deviation 0.01 the bump is seen
// from the middle of its gap and samples move onto it. A smooth bend
// (a quarter circle) is not a bump: the cubic through the ends follows it.
TEST(EvenEndParams, ABumpBetweenSamplesIsSpreadOnlyWhenAsked) {
  const std::vector<double> p = uniform(13);
  const double centre = 0.5 * (p[6] + p[7]);
  auto end = [&](double s) {
    const double d = (s - centre) / 0.01;
    return Eigen::Vector3d(s, 0.05 * std::exp(-d * d), 0.0);
  };
  std::vector<Eigen::Vector3d> ends;
  for (double s : p) ends.push_back(end(s));
  EXPECT_EQ(even_end_params(end, p, ends), p);
  igaprep::param::SpreadOptions options;
  options.chord_deviation = 0.01;
  const std::vector<double> q = even_end_params(end, p, ends, options);
  int on_bump = 0;
  for (double s : q) on_bump += std::abs(s - centre) < 0.02;
  EXPECT_GE(on_bump, 2) << "samples on the bump";
  for (std::size_t i = 1; i < q.size(); ++i) EXPECT_GT(q[i], q[i - 1]);
  auto arc = [](double s) { return Eigen::Vector3d(std::cos(s * 1.5707963), std::sin(s * 1.5707963), 0.0); };
  std::vector<Eigen::Vector3d> arc_ends;
  for (double s : p) arc_ends.push_back(arc(s));
  options.chord_deviation = 1e-4;  // below the chords' sagitta (about 1.1e-3), above the cubic's error
  EXPECT_EQ(even_end_params(arc, p, arc_ends, options), p);
}

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// Cells of an m x m grid that are not strictly convex and positively turning.
int folded_cells(const std::vector<Eigen::Vector2d>& g, int m) {
  int folded = 0;
  for (int j = 0; j + 1 < m; ++j)
    for (int i = 0; i + 1 < m; ++i) {
      const Eigen::Vector2d c[4] = {g[static_cast<std::size_t>(i + m * j)], g[static_cast<std::size_t>(i + 1 + m * j)],
                                    g[static_cast<std::size_t>(i + 1 + m * (j + 1))],
                                    g[static_cast<std::size_t>(i + m * (j + 1))]};
      bool convex = true;
      for (int k = 0; k < 4; ++k) convex = convex && cross(c[(k + 1) % 4] - c[k], c[(k + 3) % 4] - c[k]) > 0.0;
      folded += !convex;
    }
  return folded;
}

// Over a face: rows bunched along s (x = s^8) are spread along s; the
// columns, already even, keep t; the edge rows agree with the edge alone.
TEST(SpreadFaceParams, RowsAreSpreadAndEdgesDependOnTheirEndsOnly) {
  const int m = 9;
  const std::vector<double> p = uniform(m);
  auto end = [](const Eigen::Vector2d& x) { return Eigen::Vector3d(std::pow(x.x(), 8), x.y(), 0.0); };
  std::vector<Eigen::Vector3d> ends;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) ends.push_back(end({p[static_cast<std::size_t>(i)], p[static_cast<std::size_t>(j)]}));
  const std::vector<Eigen::Vector2d> q = spread_face_params(end, p, ends);
  ASSERT_EQ(q.size(), ends.size());
  std::vector<Eigen::Vector3d> bottom(ends.begin(), ends.begin() + m);
  const std::vector<double> edge = even_end_params([&](double s) { return end({s, 0.0}); }, p, bottom);
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const Eigen::Vector2d& x = q[static_cast<std::size_t>(i + m * j)];
      EXPECT_NEAR(x.y(), p[static_cast<std::size_t>(j)], 1e-12);
      EXPECT_NEAR(end(x).x(), p[static_cast<std::size_t>(i)], 0.1 / (m - 1));
      if (j == 0) EXPECT_EQ(x.x(), edge[static_cast<std::size_t>(i)]);
    }
  // A fixed side keeps its grid points; the rows inside are still spread,
  // and no cell is folded. The columns spread after the rows folded 4
  // cells; untangled, and the ends smoothed between the fixed side's
  // bunched ends and the spread top, the middle row's ends lie within an
  // even gap of even (0.67 at most; the grid's own ends are up to 5.2 gaps off).
  const std::vector<Eigen::Vector2d> kept = spread_face_params(end, p, ends, {true, false, false, false});
  EXPECT_EQ(folded_cells(kept, m), 0);
  for (int i = 0; i < m; ++i) {
    EXPECT_EQ(kept[static_cast<std::size_t>(i)], Eigen::Vector2d(p[static_cast<std::size_t>(i)], 0.0));
    EXPECT_NEAR(end(kept[static_cast<std::size_t>(i + m * (m / 2))]).x(), p[static_cast<std::size_t>(i)], 1.0 / (m - 1));
  }
}

// A fan whose focus moves across the face (x = s^(1 + 8t), y = t^(1 + 8(1 - s))):
// rows and columns spread one by one folded 5 of its 64 parameter cells,
// and once those were untangled, 11 cells of the ends' grid were still
// folded (the end map turns within a cell). Neither grid is folded now,
// the sides are still those of their ends alone, and every row of ends is
// even (largest gap over the mean 1.3; the grid's own middle row 3.9).
Eigen::Vector3d moving_fan(const Eigen::Vector2d& x) {
  return Eigen::Vector3d(std::pow(x.x(), 1.0 + 8.0 * x.y()), std::pow(x.y(), 1.0 + 8.0 * (1.0 - x.x())), 0.0);
}

// The ends of `end` at the grid p x p, first index fastest.
template <class End>
std::vector<Eigen::Vector3d> grid_ends(const End& end, const std::vector<double>& p) {
  std::vector<Eigen::Vector3d> ends;
  for (double t : p)
    for (double s : p) ends.push_back(end({s, t}));
  return ends;
}

TEST(SpreadFaceParams, AFanWhoseFocusMovesAcrossTheFaceLeavesNoCellFolded) {
  const int m = 9;
  const std::vector<double> p = uniform(m);
  const auto end = moving_fan;
  const std::vector<Eigen::Vector3d> ends = grid_ends(end, p);
  const std::vector<Eigen::Vector2d> q = spread_face_params(end, p, ends);
  EXPECT_EQ(folded_cells(q, m), 0);
  std::vector<Eigen::Vector2d> ends_2d;
  for (const Eigen::Vector2d& x : q) ends_2d.push_back(end(x).head<2>());
  EXPECT_EQ(folded_cells(ends_2d, m), 0);
  std::vector<Eigen::Vector3d> bottom(ends.begin(), ends.begin() + m);
  const std::vector<double> edge = even_end_params([&](double s) { return end({s, 0.0}); }, p, bottom);
  for (int i = 0; i < m; ++i) EXPECT_EQ(q[static_cast<std::size_t>(i)], Eigen::Vector2d(edge[static_cast<std::size_t>(i)], 0.0));
  auto gap_ratio = [&](auto&& point) {
    double largest = 0.0, total = 0.0;
    for (int i = 1; i < m; ++i) {
      const double gap = (end(point(i)) - end(point(i - 1))).norm();
      largest = std::max(largest, gap);
      total += gap;
    }
    return largest / (total / (m - 1));
  };
  const int mid = m / 2;
  const double grid = gap_ratio([&](int i) { return Eigen::Vector2d(p[static_cast<std::size_t>(i)], p[mid]); });
  for (int j = 0; j < m; ++j) {
    const double spread = gap_ratio([&](int i) { return q[static_cast<std::size_t>(i + m * j)]; });
    EXPECT_LT(spread, 0.4 * grid) << "row " << j << ": " << spread << ", the grid's middle row " << grid;
  }
}

// The face's ends are traced on all cores; the result is the same on one
// (the moved parameters bit for bit), whatever order the threads run in.
TEST(SpreadFaceParams, TheSameOnOneCoreAsOnAll) {
  const int m = 9;
  const std::vector<double> p = uniform(m);
  const auto end = moving_fan;
  const std::vector<Eigen::Vector3d> ends = grid_ends(end, p);
  igaprep::set_thread_count(1);
  const std::vector<Eigen::Vector2d> one = spread_face_params(end, p, ends);
  igaprep::set_thread_count(0);
  const std::vector<Eigen::Vector2d> all = spread_face_params(end, p, ends);
  ASSERT_EQ(one.size(), all.size());
  for (std::size_t q = 0; q < one.size(); ++q) EXPECT_EQ(one[q], all[q]) << q;
  EXPECT_NE(one[static_cast<std::size_t>(m + 1)], Eigen::Vector2d(p[1], p[1]));  // the face was spread
}
}  // namespace
