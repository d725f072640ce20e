// Spreading a shell face's streamline ends evenly (param/shell_spread.h).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

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
  // A fixed side keeps its grid points; the rows inside are still spread.
  const std::vector<Eigen::Vector2d> kept = spread_face_params(end, p, ends, {true, false, false, false});
  for (int i = 0; i < m; ++i) {
    EXPECT_EQ(kept[static_cast<std::size_t>(i)], Eigen::Vector2d(p[static_cast<std::size_t>(i)], 0.0));
    EXPECT_NEAR(end(kept[static_cast<std::size_t>(i + m * (m / 2))]).x(), p[static_cast<std::size_t>(i)], 0.2 / (m - 1));
  }
}

}  // namespace
