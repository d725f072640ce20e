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
  std::array<int, 3> lo, hi;  // neighbour cells to look into, per direction
  for (int d = 0; d < 3; ++d) {
    const double s = std::floor(p[d] / cell_);
    if (!(std::abs(s) < 1e17))
      throw bad_input("point merger: tolerance " + std::to_string(tol_) + " too small for the coordinate " +
                      std::to_string(p[d]));
    key[d] = static_cast<std::int64_t>(s);
    lo[d] = p[d] - s * cell_ <= tol_ ? -1 : 0;
    hi[d] = (s + 1.0) * cell_ - p[d] <= tol_ ? 1 : 0;
  }
  int best = -1;
  double best_dist = tol_;
  for (int dx = lo[0]; dx <= hi[0]; ++dx)
    for (int dy = lo[1]; dy <= hi[1]; ++dy)
      for (int dz = lo[2]; dz <= hi[2]; ++dz) {
        const auto it = first_.find(hash({{key[0] + dx, key[1] + dy, key[2] + dz}}));
        if (it == first_.end()) continue;
        for (int v = it->second; v >= 0; v = next_[static_cast<std::size_t>(v)]) {
          const double dist = (points_[static_cast<std::size_t>(v)] - p).norm();
          if (dist < best_dist || (dist == best_dist && (best < 0 || v < best))) best_dist = dist, best = v;
        }
      }
  if (best >= 0) return {best, false};
  const int v = static_cast<int>(points_.size());
  points_.push_back(p);
  // hash collisions only cost a distance test
  const auto [it, added] = first_.try_emplace(hash(key), v);
  next_.push_back(added ? -1 : it->second);
  if (!added) it->second = v;
  return {v, true};
}

}  // namespace igaprep
