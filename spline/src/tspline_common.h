#pragma once
// Internal to the T-spline model: index space <-> parameters of a patch,
// and the rectangles a T-mesh has on one side of its patch.
#include <array>
#include <vector>

#include "igaprep/spline/multipatch.h"
#include "igaprep/spline/side.h"
#include "igaprep/spline/tmesh.h"

namespace igaprep::spline::detail {

// The parameter of index coordinate x, `breaks` the distinct knots
// (unique_knots: element e spans [breaks[e], breaks[e + 1]]), clamped to the
// domain: the repeated end knots numbered beyond it are the end knot again.
double index_to_parameter(const std::vector<double>& breaks, TCoord x);

// A box's face on a side of the patch, in the two tangent directions (increasing).
struct FaceRect {
  std::array<TCoord, 2> lo{}, hi{};
  int box = 0;
};
std::vector<FaceRect> face_rects(const TMesh& mesh, Side side);

}  // namespace igaprep::spline::detail
