#pragma once
// The element stiffness kernel of isotropic linear elasticity, given the
// physical basis gradients at the quadrature points of one element.
#include <Eigen/Core>

#include "igaprep/iga_check/elasticity_material.h"

namespace igaprep::iga_check {

// Inputs:
//   grad: nq x (3 n) basis gradients, columns [dN/dx | dN/dy | dN/dz] (n basis
//         functions each), one row per quadrature point;
//   wdet: nq quadrature weight times |det J| per point;
//   lame: the material.
// Outputs:
//   Ke:   (3 n) x (3 n) element stiffness, component-blocked: row i*n + a is
//         component i of basis function a.
//   work: scratch of size nq x (3 n), reused between calls.
// K_{ai,bj} = sum_q w_q (lambda dN_a/dx_i dN_b/dx_j + mu dN_a/dx_j dN_b/dx_i
//                        + mu delta_ij grad N_a . grad N_b)
void element_stiffness(const Eigen::MatrixXd& grad, const Eigen::VectorXd& wdet, const LameParameters& lame,
                       Eigen::MatrixXd& Ke, Eigen::MatrixXd& work);

}  // namespace igaprep::iga_check
