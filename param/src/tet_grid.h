#pragma once
// Internal to FieldProbe: tets bucketed in a uniform grid by their bounding
// boxes, to find the tet holding a point without a walk. A walk can leave a
// non-convex mesh on its way to a point inside it (across a re-entrant edge
// of the boundary); the grid decides such a point in a few tets.
#include <array>
#include <vector>

#include <Eigen/Core>

namespace igaprep::param::detail {

class TetGrid {
 public:
  TetGrid(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T);
  // The tet holding p (barycentric coordinates >= -1e-12), the one p is
  // deepest in when several do; -1 when none. *bary as locate_in_tets.
  int locate(const Eigen::Vector3d& p, Eigen::Vector4d* bary) const;
  // The same with locate_in_tets's scan's rule: coordinates > -1e-9, the
  // first tet (by index) of those p is deepest in. The scan's answer without
  // its pass over every tet: a tet holding p meets p's cell.
  int locate_as_scan(const Eigen::Vector3d& p, Eigen::Vector4d* bary) const;

 private:
  int cell_index(const std::array<int, 3>& c) const { return c[0] + n_[0] * (c[1] + n_[1] * c[2]); }
  std::array<int, 3> cell_of(const Eigen::Vector3d& p) const;
  int deepest(const Eigen::Vector3d& p, Eigen::Vector4d* bary, double tolerance, bool later_ties) const;

  const Eigen::MatrixXd& V_;
  const Eigen::MatrixXi& T_;
  Eigen::Vector3d lo_ = Eigen::Vector3d::Zero(), size_ = Eigen::Vector3d::Ones();
  std::array<int, 3> n_{{1, 1, 1}};
  std::vector<int> start_, tets_;  // per cell (CSR) the tets whose bounding box meets it
};

}  // namespace igaprep::param::detail
