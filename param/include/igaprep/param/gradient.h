#pragma once
// Gradients of piecewise-linear fields: constant per cell (section 2.1 of the
// seed paper: grad u = sum_j u_j grad phi_j in each tet) and averaged per vertex.
#include <Eigen/Core>

namespace igaprep::param {

// Inputs: V (#V x 3); cells (#C x 4 tets or #C x 3 triangles); u (#V) field.
// Output: G (#C x 3), the constant gradient of u in each cell (for triangles
// it lies in the triangle's plane). Throws bad_input for a degenerate cell.
Eigen::MatrixXd cell_gradients(const Eigen::MatrixXd& V, const Eigen::MatrixXi& cells, const Eigen::VectorXd& u);

// Inputs: as above. Output: #V x 3, at each vertex the volume- (area-)
// weighted mean of the gradients of the cells around it; 0 for unused vertices.
Eigen::MatrixXd vertex_gradients(const Eigen::MatrixXd& V, const Eigen::MatrixXi& cells, const Eigen::VectorXd& u);

// Gradients of the barycentric (hat) functions of one cell: rows 0..k-1 of
// `grad_phi` (k = 4 for a tet, 3 for a triangle). Returns the signed volume
// (tets) or the area (triangles); 0 for a degenerate cell (grad_phi then unset).
double tet_barycentric_gradients(const Eigen::Vector3d& x0, const Eigen::Vector3d& x1, const Eigen::Vector3d& x2,
                                 const Eigen::Vector3d& x3, Eigen::Matrix<double, 4, 3>& grad_phi);
double tri_barycentric_gradients(const Eigen::Vector3d& x0, const Eigen::Vector3d& x1, const Eigen::Vector3d& x2,
                                 Eigen::Matrix<double, 3, 3>& grad_phi);

}  // namespace igaprep::param
