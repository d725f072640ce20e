#include "igaprep/core/point_merger.h"

#include <cmath>
#include <string>

#include "igaprep/core/error.h"

namespace igaprep {

namespace {
std::uint64_t hash(const std::array<std::int64_t, 3>& k) {
  std::uint64_t h = 1469598103934665603ull;
  for (std::int64_t x : k) h = (h ^ static_cast<std::uint64_t>(x)) * 1099511628211ull + (h >> 29);
  return h;
}
}  // namespace

std::pair<int, bool> PointMerger::insert(const Eigen::Vector3d& p) {
  std::array<std::int64_t, 3> key;
  for (int d = 0; d < 3; ++d) {
    const double s = std::floor(p[d] / tol_);
    if (!(std::abs(s) < 1e17))
      throw bad_input("point merger: tolerance " + std::to_string(tol_) + " too small for the coordinate " +
                      std::to_string(p[d]));
    key[d] = static_cast<std::int64_t>(s);
  }
  int best = -1;
  double best_dist = tol_;
  for (int dx = -1; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dz = -1; dz <= 1; ++dz) {
        const auto it = grid_.find(hash({{key[0] + dx, key[1] + dy, key[2] + dz}}));
        if (it == grid_.end()) continue;
        for (int v : it->second) {
          const double dist = (points_[static_cast<std::size_t>(v)] - p).norm();
          if (dist <= best_dist) best_dist = dist, best = v;
        }
      }
  if (best >= 0) return {best, false};
  const int v = static_cast<int>(points_.size());
  points_.push_back(p);
  grid_[hash(key)].push_back(v);  // hash collisions only cost a distance test
  return {v, true};
}

}  // namespace igaprep
