#pragma once
// Merges points closer than a tolerance into one vertex: a hash grid of
// cells a multiple of that size (a point's match is in its own cell, or in a
// neighbour across a cell face less than the tolerance away, so most points
// look into one cell); the nearest earlier point within the tolerance wins.
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
  explicit PointMerger(double tol) : tol_(tol), cell_(kCellsPerTolerance * tol) {}

  // Returns the vertex index of p and whether it is a new vertex. Throws
  // bad_input when a coordinate divided by the tolerance overflows the grid.
  std::pair<int, bool> insert(const Eigen::Vector3d& p);

  const std::vector<Eigen::Vector3d>& points() const { return points_; }

 private:
  static constexpr double kCellsPerTolerance = 64.0;
  double tol_, cell_;
  std::vector<Eigen::Vector3d> points_;
  std::vector<int> next_;                          // the next point of the same cell, or -1
  std::unordered_map<std::uint64_t, int> first_;   // a cell's newest point
};

}  // namespace igaprep
