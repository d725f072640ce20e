#pragma once
// P1 finite-element stiffness matrices (the discrete Laplace operator of the
// seed paper, section 2.1) on tet meshes and on triangle surfaces.
#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace igaprep::param {

// Inputs: V (#V x 3) vertex positions; T (#T x 4) tets (either orientation).
// Output: K (#V x #V), K(i,j) = sum over tets of vol * grad(phi_i) . grad(phi_j):
// symmetric positive semi-definite, rows sum to zero (constants are in the kernel).
// Assembled straight into compressed column storage (no triplet sort), so a
// million tets take well under a second. Throws bad_input naming the tet when
// a tet is degenerate (zero volume) or references a vertex out of range.
Eigen::SparseMatrix<double> tet_stiffness(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T);

// Inputs: V (#V x 3), F (#F x 3) triangles of a surface (need not be planar or closed).
// Output: the cotangent Laplacian with the sign that makes it positive
// semi-definite: K(i,j) = -(cot a_ij + cot b_ij) / 2 off the diagonal, rows sum to zero.
// (Identical to the P1 stiffness matrix of the piecewise-linear surface.)
// Throws bad_input naming the triangle when one is degenerate (zero area).
Eigen::SparseMatrix<double> tri_cotan_laplacian(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);

// Either of the two by the number of columns of `cells` (4: tets, 3: triangles).
Eigen::SparseMatrix<double> stiffness_matrix(const Eigen::MatrixXd& V, const Eigen::MatrixXi& cells);

}  // namespace igaprep::param
