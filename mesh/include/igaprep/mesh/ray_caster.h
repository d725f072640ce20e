#pragma once
// First hits of rays on a triangle mesh (a CGAL AABB tree over its faces).
#include <memory>
#include <optional>

#include <Eigen/Core>

#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::mesh {

struct RayHit {
  int face = -1;
  double distance = 0.0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
};

class RayCaster {
 public:
  explicit RayCaster(const TriMesh& mesh);
  ~RayCaster();
  RayCaster(const RayCaster&) = delete;
  RayCaster& operator=(const RayCaster&) = delete;

  // The nearest face other than `skip_face` that the ray from `origin` along
  // `direction` (need not be unit) meets; nullopt when the ray leaves the mesh.
  std::optional<RayHit> first_hit(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                  int skip_face = -1) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace igaprep::mesh
