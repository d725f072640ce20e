#pragma once
// A triangle surface as plain arrays (libigl style): V is #V x 3 vertex
// positions, F is #F x 3 vertex indices (0-based), counter-clockwise seen from
// outside for closed surfaces after validation.
#include <Eigen/Core>

namespace igaprep::mesh {

struct TriMesh {
  Eigen::MatrixXd V;  // #V x 3
  Eigen::MatrixXi F;  // #F x 3
};

}  // namespace igaprep::mesh
