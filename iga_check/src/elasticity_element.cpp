#include "igaprep/iga_check/elasticity_element.h"

namespace igaprep::iga_check {

void element_stiffness(const Eigen::MatrixXd& grad, const Eigen::VectorXd& wdet, const LameParameters& lame,
                       Eigen::MatrixXd& Ke, Eigen::MatrixXd& work) {
  const Eigen::Index n3 = grad.cols();
  const Eigen::Index n = n3 / 3;
  // M = G^T W G holds every product sum_q w dN_a/dx_i dN_b/dx_j in block (i, j);
  // one symmetric rank-nq update (half the flops of a general product) does
  // all the work (tensor-product kernels gain little at degree 2-3).
  work = wdet.cwiseMax(0.0).cwiseSqrt().asDiagonal() * grad;
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n3, n3);
  M.selfadjointView<Eigen::Lower>().rankUpdate(work.transpose());
  M.triangularView<Eigen::StrictlyUpper>() = M.transpose();
  Ke.resize(n3, n3);
  const Eigen::MatrixXd trace = M.block(0, 0, n, n) + M.block(n, n, n, n) + M.block(2 * n, 2 * n, n, n);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      auto K = Ke.block(i * n, j * n, n, n);
      K = lame.lambda * M.block(i * n, j * n, n, n) + lame.mu * M.block(j * n, i * n, n, n);
      if (i == j) K += lame.mu * trace;
    }
}

}  // namespace igaprep::iga_check
