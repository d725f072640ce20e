#pragma once
// Lumped (diagonal) mass: the volume or area each vertex stands for, used to
// weight per-vertex quantities (vertex gradients, L2 norms, surface integrals).
#include <Eigen/Core>

namespace igaprep::param {

// Inputs: V (#V x 3); cells (#C x 4 tets or #C x 3 triangles).
// Output: M (#V), M(i) = sum over cells containing i of |cell| / (cells.cols()),
// so M.sum() is the total volume (tets) or area (triangles); vertices in no cell get 0.
Eigen::VectorXd lumped_mass(const Eigen::MatrixXd& V, const Eigen::MatrixXi& cells);

// Inputs: V, cells as above. Output: #C unsigned volumes (tets) or areas (triangles).
Eigen::VectorXd cell_measures(const Eigen::MatrixXd& V, const Eigen::MatrixXi& cells);

}  // namespace igaprep::param
