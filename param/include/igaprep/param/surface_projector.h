#pragma once
// Closest points on a triangle surface (CGAL's AABB tree): puts sampled
// points back onto T1 or a Ti after they were moved across a block face, and
// finds the (u, v) triangle holding a point for SheetSampler (flat, z = 0);
// slides control points along T1 and the Ti (spline/optimize_jacobian.h).
#include <memory>
#include <vector>

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

  // The unit normal of row `triangle` of F (zero for a flat triangle).
  Eigen::Vector3d normal(int triangle) const;

  // Where a point at `from` (on or near the surface) goes when it is moved
  // towards `to` along the surface: the closest point to `to`, offset along
  // the normal by `from`'s signed distance (a fitted side's control points
  // lie a little off the surface they approximate).
  Eigen::Vector3d slide(const Eigen::Vector3d& from, const Eigen::Vector3d& to) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

struct DecompositionMesh;  // decomposition_mesh.h

// One projector per input surface of H: T1..Tn, in order.
std::vector<SurfaceProjector> surface_projectors(const DecompositionMesh& H);

}  // namespace igaprep::param
