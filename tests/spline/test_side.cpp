// The Side type: G+Smo's numbering 1..6 = u0, u1, v0, v1, w0, w1 turned into
// directions, ends and array positions in one place.
#include <gtest/gtest.h>

#include "igaprep/core/error.h"
#include "igaprep/spline/side.h"

using igaprep::spline::Side;

TEST(SplineSide, DirectionParameterAndIndex) {
  const int direction[6] = {0, 0, 1, 1, 2, 2};
  const bool parameter[6] = {false, true, false, true, false, true};
  int k = 0;
  for (const Side s : Side::all()) {
    EXPECT_EQ(s.index(), k + 1);
    EXPECT_EQ(s.array_index(), k);
    EXPECT_EQ(s.direction(), direction[k]);
    EXPECT_EQ(s.parameter(), parameter[k]);
    EXPECT_EQ(Side::of(s.direction(), s.parameter()).index(), s.index());
    EXPECT_EQ(s.opposite().direction(), s.direction());
    EXPECT_NE(s.opposite().parameter(), s.parameter());
    EXPECT_EQ(s.opposite().opposite().index(), s.index());
    const auto t = s.tangent_directions();
    EXPECT_LT(t[0], t[1]);
    EXPECT_NE(t[0], s.direction());
    EXPECT_NE(t[1], s.direction());
    ++k;
  }
  EXPECT_EQ(k, 6);
  EXPECT_EQ(igaprep::spline::kU0.index(), 1);
  EXPECT_EQ(igaprep::spline::kW1.index(), 6);
  EXPECT_EQ(igaprep::spline::kV1.opposite().index(), igaprep::spline::kV0.index());
}

TEST(SplineSide, InvalidSidesAreRefused) {
  for (const int bad : {0, 7, -1}) {
    const Side s(bad);
    EXPECT_FALSE(s.valid());
    EXPECT_THROW(s.direction(), igaprep::Error);
    EXPECT_THROW(s.parameter(), igaprep::Error);
    EXPECT_THROW(s.array_index(), igaprep::Error);
    EXPECT_THROW(s.opposite(), igaprep::Error);
  }
  EXPECT_THROW(Side::of(3, false), igaprep::Error);
  EXPECT_FALSE(Side().valid());
}
