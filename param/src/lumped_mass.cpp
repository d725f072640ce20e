#include "igaprep/param/lumped_mass.h"

#include "cell_geometry.h"

namespace igaprep::param {

Eigen::VectorXd cell_measures(const Eigen::MatrixXd& V, const Eigen::MatrixXi& cells) {
  detail::check_cells(V, cells, "cell_measures");
  Eigen::VectorXd m(cells.rows());
  for (Eigen::Index c = 0; c < cells.rows(); ++c) m(c) = detail::cell_measure(V, cells, c);
  return m;
}

Eigen::VectorXd lumped_mass(const Eigen::MatrixXd& V, const Eigen::MatrixXi& cells) {
  const Eigen::VectorXd m = cell_measures(V, cells);
  Eigen::VectorXd M = Eigen::VectorXd::Zero(V.rows());
  const double share = 1.0 / static_cast<double>(cells.cols());
  for (Eigen::Index c = 0; c < cells.rows(); ++c)
    for (Eigen::Index k = 0; k < cells.cols(); ++k) M(cells(c, k)) += share * m(c);
  return M;
}

}  // namespace igaprep::param
