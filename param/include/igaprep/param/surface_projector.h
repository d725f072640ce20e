#pragma once
// Closest points on a triangle surface (CGAL's AABB tree): puts sampled
// points back onto T1 or a Ti after they were moved across a block face, and
// finds the (u, v) triangle holding a point for SheetSampler (flat, z = 0).
#include <memory>

#include <Eigen/Core>

namespace igaprep::param {

class SurfaceProjector {
 public:
  // Inputs: vertices V (#V x 3) and triangles F (#F x 3, rows of V); #F > 0.
  SurfaceProjector(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);
  ~SurfaceProjector();
  SurfaceProjector(SurfaceProjector&&) noexcept;
  SurfaceProjector& operator=(SurfaceProjector&&) noexcept;

  // The closest point on the surface; `triangle` (if given) receives the
  // row of F it lies on.
  Eigen::Vector3d closest(const Eigen::Vector3d& p, int* triangle = nullptr) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace igaprep::param
