#pragma once
// Point queries on a triangle sheet through its (u, v) parameterization: the
// 3D point, the unit normal and the tangents dX/du, dX/dv at any (u, v) of the
// parameter domain, interpolated linearly inside the (u, v) triangle holding
// it. The volume parameterization (volume_param.h) samples the base surface M this way.
#include <memory>

#include <Eigen/Core>

#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/param/surface_projector.h"

namespace igaprep::param {

struct SheetPoint {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, the side the sheet's triangles face
  Eigen::Vector3d du = Eigen::Vector3d::Zero(), dv = Eigen::Vector3d::Zero();  // dX/du, dX/dv (vertex averages)
  int triangle = -1;
  Eigen::Vector3d bary = Eigen::Vector3d::Zero();  // in that triangle
};

class SheetSampler {
 public:
  // Inputs: the sheet and its (u, v) per vertex (#V x 2, a bijective map:
  // every triangle positively oriented), rounds of one-ring smoothing of the
  // normals and tangents. Builds a search tree of the (u, v) triangles and
  // the per-vertex normals and tangents (area-weighted).
  SheetSampler(const mesh::TriMesh& sheet, const Eigen::MatrixXd& uv, int smoothing_rounds = 3);
  ~SheetSampler();
  SheetSampler(const SheetSampler&) = delete;
  SheetSampler& operator=(const SheetSampler&) = delete;

  // The sheet at (u, v); a point outside the (u, v) image (round-off at the
  // domain's sides) is taken at the nearest point of the image.
  SheetPoint at(const Eigen::Vector2d& uv) const;

 private:
  const mesh::TriMesh& sheet_;
  const Eigen::MatrixXd& uv_;
  Eigen::MatrixXd normal_, du_, dv_;  // per vertex
  std::unique_ptr<SurfaceProjector> flat_;  // the (u, v) triangles at z = 0
};

}  // namespace igaprep::param
