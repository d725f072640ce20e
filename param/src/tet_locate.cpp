#include <algorithm>

#include "cell_geometry.h"
#include "igaprep/param/tet_topology.h"

namespace igaprep::param {

int locate_in_tets(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T, const TetTopology& topology,
                   const Eigen::Vector3d& p, int hint, Eigen::Vector4d* bary, bool scan_when_walk_leaves) {
  const int m = static_cast<int>(T.rows());
  if (m == 0) return -1;
  auto coords = [&](int c, Eigen::Vector4d& b) {
    Eigen::Matrix<double, 4, 3> gp;  // gradients of the four barycentric coordinates
    if (detail::cell_grad_phi(V, T, c, gp) == 0.0) return false;
    const Eigen::Vector3d r = p - detail::vrow(V, T(c, 0));
    for (int k = 1; k < 4; ++k) b(k) = gp.row(k).dot(r);
    b(0) = 1.0 - b(1) - b(2) - b(3);
    return true;
  };
  Eigen::Vector4d b;
  // Visibility walk towards the point; non-Delaunay meshes can make it cycle
  // and non-convex domains can make it leave, so it is bounded and backed by a scan.
  int c = (hint >= 0 && hint < m) ? hint : 0;
  for (int it = 0; it < 20000; ++it) {
    if (!coords(c, b)) break;
    int k;
    if (b.minCoeff(&k) >= -1e-12) {
      if (bary) *bary = b.cwiseMax(0.0) / b.cwiseMax(0.0).sum();
      return c;
    }
    c = topology.neighbor(c, k);
    if (c < 0) {
      if (!scan_when_walk_leaves) return -1;
      break;
    }
  }
  int best = -1;
  double best_min = -1e-9;
  for (int x = 0; x < m; ++x) {
    // Cheap bounding-box rejection first.
    bool outside = false;
    for (int a = 0; a < 3 && !outside; ++a) {
      double lo = V(T(x, 0), a), hi = lo;
      for (int k = 1; k < 4; ++k) lo = std::min(lo, V(T(x, k), a)), hi = std::max(hi, V(T(x, k), a));
      outside = p(a) < lo - 1e-9 * (hi - lo) || p(a) > hi + 1e-9 * (hi - lo);
    }
    if (outside || !coords(x, b)) continue;
    if (b.minCoeff() > best_min) best_min = b.minCoeff(), best = x;
  }
  if (best >= 0 && bary) {
    coords(best, b);
    *bary = b.cwiseMax(0.0) / b.cwiseMax(0.0).sum();
  }
  return best;
}

}  // namespace igaprep::param
