#pragma once
// Merges points closer than a tolerance into one vertex: a hash grid of
// cells of that size (a point's match is in its own or a neighbouring cell;
// the nearest earlier point within the tolerance wins).
#include <array>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace igaprep {

class PointMerger {
 public:
  // tol > 0 and finite (not checked here: callers check their own input).
  explicit PointMerger(double tol) : tol_(tol) {}

  // Returns the vertex index of p and whether it is a new vertex. Throws
  // bad_input when a coordinate divided by the tolerance overflows the grid.
  std::pair<int, bool> insert(const Eigen::Vector3d& p);

  const std::vector<Eigen::Vector3d>& points() const { return points_; }

 private:
  double tol_;
  std::vector<Eigen::Vector3d> points_;
  std::unordered_map<std::uint64_t, std::vector<int>> grid_;
};

}  // namespace igaprep
