#include "igaprep/param/rim_reach.h"

#include <algorithm>
#include <limits>

#include "igaprep/param/surface_projector.h"
#include "cell_geometry.h"

namespace igaprep::param {

namespace {

// Distance from p to the nearest of the segments [a[s], b[s]].
template <int N>
double distance_to_segments(const Eigen::Matrix<double, N, 1>& p, const std::vector<Eigen::Matrix<double, N, 1>>& a,
                            const std::vector<Eigen::Matrix<double, N, 1>>& b) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t s = 0; s < a.size(); ++s) best = std::min(best, detail::distance_to_segment<N>(p, a[s], b[s]));
  return best;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

}  // namespace

RimReach rim_reach_cap(const mesh::TriMesh& sheet, const Eigen::MatrixXd& uv, const std::vector<std::vector<int>>& loops,
                       const SurfaceProjector& rim, double nominal, double reach) {
  std::vector<Eigen::Vector2d> a2, b2;
  std::vector<Eigen::Vector3d> a3, b3;
  std::vector<char> on_boundary(static_cast<std::size_t>(sheet.V.rows()), 0);
  for (const auto& loop : loops)
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const int i = loop[k], j = loop[(k + 1) % loop.size()];
      on_boundary[static_cast<std::size_t>(i)] = 1;
      a2.push_back(uv.row(i).transpose()), b2.push_back(uv.row(j).transpose());
      a3.push_back(sheet.V.row(i).transpose()), b3.push_back(sheet.V.row(j).transpose());
    }
  RimReach out;
  out.cap = nominal;
  std::vector<double> allowed, thin_r;
  for (Eigen::Index v = 0; v < sheet.V.rows(); ++v) {
    if (on_boundary[static_cast<std::size_t>(v)]) continue;
    const double delta = distance_to_segments<2>(uv.row(v).transpose(), a2, b2);
    if (!(delta < nominal)) continue;
    const Eigen::Vector3d p = sheet.V.row(v).transpose();
    const double D = distance_to_segments<3>(p, a3, b3);
    const double r = (rim.closest(p) - p).norm();
    ++out.considered;
    if (D > reach * r) {
      ++out.thin;
      thin_r.push_back(r);
      allowed.push_back(std::min(nominal, delta * reach * r / D));
    } else {
      allowed.push_back(nominal);
    }
  }
  if (!allowed.empty()) {
    const auto q = allowed.begin() + static_cast<std::ptrdiff_t>(allowed.size() / 4);
    std::nth_element(allowed.begin(), q, allowed.end());
    out.cap = *q;
  }
  out.half_thickness = median(thin_r);
  return out;
}

}  // namespace igaprep::param
