#pragma once
// Internal to the extraction-form solve: the lower triangle of the
// stiffness matrix (dof 3 f + i) laid out once from the functions that
// share an element, element matrices added in place (no triplets: they
// took 1.6 GB and most of the assembly on sphere2).
#include <Eigen/Core>
#include <vector>

#include "elasticity_pattern.h"
#include "igaprep/spline/extraction_model.h"

namespace igaprep::iga_check::detail {

class BlockLowerMatrix {
 public:
  explicit BlockLowerMatrix(const spline::ExtractionModel& m);
  // Ke: 3n x 3n over the element's functions (dof 3 r + i).
  void add(const std::vector<int>& functions, const Eigen::MatrixXd& Ke);
  SparseMatrix& matrix() { return K_; }
  const SparseMatrix& matrix() const { return K_; }

 private:
  std::vector<std::vector<int>> lower_;  // per function g: the functions f >= g sharing an element with it, ascending
  SparseMatrix K_;
};

}  // namespace igaprep::iga_check::detail
