#include "tspline_common.h"

namespace igaprep::spline::detail {

double index_to_parameter(const std::vector<double>& breaks, TCoord x) {
  const TCoord end = static_cast<TCoord>(breaks.size() - 1) * kTScale;
  if (x <= 0) return breaks.front();
  if (x >= end) return breaks.back();
  const std::size_t e = static_cast<std::size_t>(x / kTScale);
  const double f = static_cast<double>(x % kTScale) / static_cast<double>(kTScale);
  return (1.0 - f) * breaks[e] + f * breaks[e + 1];
}

std::vector<FaceRect> face_rects(const TMesh& mesh, Side side) {
  const std::size_t n = static_cast<std::size_t>(side.direction());
  const std::array<int, 2> t = side.tangent_directions();
  const TCoord at = side.parameter() ? mesh.extent(static_cast<int>(n)) : 0;
  std::vector<FaceRect> out;
  for (std::size_t b = 0; b < mesh.boxes().size(); ++b) {
    const TBox& q = mesh.boxes()[b];
    if ((side.parameter() ? q.hi[n] : q.lo[n]) != at) continue;
    FaceRect r;
    for (std::size_t k = 0; k < 2; ++k) {
      r.lo[k] = q.lo[static_cast<std::size_t>(t[k])];
      r.hi[k] = q.hi[static_cast<std::size_t>(t[k])];
    }
    r.box = static_cast<int>(b);
    out.push_back(r);
  }
  return out;
}

}  // namespace igaprep::spline::detail
