#pragma once
// Internal to the elasticity solver: the sparsity pattern of the stiffness
// matrix, built once from the control-point adjacency of the elements, and
// the scatter of element matrices into it.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

namespace igaprep::iga_check::detail {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// Lower-triangular scalar pattern over the free components and the positions
// needed to scatter element matrices into it.
struct StiffnessPattern {
  std::vector<int> eq;               // 3*g + i -> equation, or -1 when constrained
  std::vector<int> free_before;      // 3*g + i -> free components of g before i
  std::vector<int> free_count;       // per g
  std::vector<long long> blk_start;  // per column block g: rows r >= g in blk_rows[blk_start[g]..]
  std::vector<int> blk_rows;
  std::vector<long long> blk_cum;    // free scalar rows of earlier off-diagonal blocks of the column
  SparseMatrix K;                    // the pattern with zero values
};

// Inputs: the global control points of every element; ncp control points;
// equation numbers (3*g + i -> equation or -1). Throws bad_input when the
// matrix would exceed 2^31 non-zeros.
StiffnessPattern build_stiffness_pattern(const std::vector<std::vector<int>>& element_cps, int ncp,
                                         const std::vector<int>& equation);

// Adds an element matrix (component-blocked, see element_stiffness) of the
// element with global control points gid to P.K.
void scatter(StiffnessPattern& P, const std::vector<int>& gid, const Eigen::MatrixXd& Ke);

}  // namespace igaprep::iga_check::detail
