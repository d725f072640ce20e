#pragma once
// A tetrahedral mesh as plain arrays, with a material per tet and the faces
// that carry an input surface.
#include <Eigen/Core>

namespace igaprep::mesh {

struct TetMesh {
  Eigen::MatrixXd V;         // #V x 3 vertex positions
  Eigen::MatrixXi T;         // #T x 4 vertex indices, positively oriented
                             // (det[v1-v0, v2-v0, v3-v0] > 0)
  Eigen::VectorXi material;  // #T: 0 between T1 and T2, ..., n-1 inside Tn
  Eigen::MatrixXi F;         // #F x 3 marked faces (each a face of some tet)
  Eigen::VectorXi F_marker;  // #F: index of the surface the face lies on
                             // (0..n-1 for T1..Tn, n.. for embedded surfaces)
};

}  // namespace igaprep::mesh
