#include "igaprep/param/gradient.h"

#include <cmath>
#include <string>

#include "igaprep/core/error.h"
#include "cell_geometry.h"

namespace igaprep::param {

double tet_barycentric_gradients(const Eigen::Vector3d& x0, const Eigen::Vector3d& x1, const Eigen::Vector3d& x2,
                                 const Eigen::Vector3d& x3, Eigen::Matrix<double, 4, 3>& grad_phi) {
  const Eigen::Vector3d e1 = x1 - x0, e2 = x2 - x0, e3 = x3 - x0;
  const Eigen::Vector3d c23 = e2.cross(e3);
  const double det = e1.dot(c23);
  // Degenerate relative to the tet's own size, so the test is scale free.
  const double len = std::max({e1.squaredNorm(), e2.squaredNorm(), e3.squaredNorm(), (x2 - x1).squaredNorm(),
                               (x3 - x1).squaredNorm(), (x3 - x2).squaredNorm()});
  if (!(std::abs(det) > 1e-13 * len * std::sqrt(len))) return 0.0;
  grad_phi.row(1) = c23 / det;
  grad_phi.row(2) = e3.cross(e1) / det;
  grad_phi.row(3) = e1.cross(e2) / det;
  grad_phi.row(0) = -(grad_phi.row(1) + grad_phi.row(2) + grad_phi.row(3));
  return det / 6.0;
}

double tri_barycentric_gradients(const Eigen::Vector3d& x0, const Eigen::Vector3d& x1, const Eigen::Vector3d& x2,
                                 Eigen::Matrix<double, 3, 3>& grad_phi) {
  const Eigen::Vector3d n = (x1 - x0).cross(x2 - x0);
  const double n2 = n.squaredNorm();
  const double len = std::max({(x1 - x0).squaredNorm(), (x2 - x0).squaredNorm(), (x2 - x1).squaredNorm()});
  if (!(n2 > 1e-26 * len * len)) return 0.0;
  // grad phi_i = n x e_i / |n|^2 with e_i the edge opposite vertex i (counter-clockwise).
  grad_phi.row(0) = n.cross(x2 - x1) / n2;
  grad_phi.row(1) = n.cross(x0 - x2) / n2;
  grad_phi.row(2) = n.cross(x1 - x0) / n2;
  return 0.5 * std::sqrt(n2);
}

namespace detail {

void check_cells(const Eigen::MatrixXd& V, const Eigen::MatrixXi& cells, const char* who) {
  if (cells.cols() != 3 && cells.cols() != 4)
    throw bad_input(std::string(who) + ": cells must have 3 (triangles) or 4 (tets) columns, got " +
                    std::to_string(cells.cols()));
  if (V.cols() != 3 && V.rows() > 0)
    throw bad_input(std::string(who) + ": vertex matrix must have 3 columns, got " + std::to_string(V.cols()));
  const int nv = static_cast<int>(V.rows());
  for (Eigen::Index c = 0; c < cells.rows(); ++c)
    for (Eigen::Index k = 0; k < cells.cols(); ++k)
      if (cells(c, k) < 0 || cells(c, k) >= nv)
        throw bad_input(std::string(who) + ": cell " + std::to_string(c) + " references vertex " +
                        std::to_string(cells(c, k)) + ", but there are " + std::to_string(nv) + " vertices");
}

[[noreturn]] void throw_degenerate(const char* who, Eigen::Index c, int k) {
  throw bad_input(std::string(who) + ": " + (k == 4 ? "tet " : "triangle ") + std::to_string(c) +
                  " is degenerate (zero " + (k == 4 ? "volume" : "area") + ")");
}

}  // namespace detail

Eigen::MatrixXd cell_gradients(const Eigen::MatrixXd& V, const Eigen::MatrixXi& cells, const Eigen::VectorXd& u) {
  detail::check_cells(V, cells, "cell_gradients");
  if (u.size() != V.rows()) throw bad_input("cell_gradients: field has " + std::to_string(u.size()) +
                                            " values for " + std::to_string(V.rows()) + " vertices");
  Eigen::MatrixXd G(cells.rows(), 3);
  for (Eigen::Index c = 0; c < cells.rows(); ++c) {
    if (cells.cols() == 4) {
      Eigen::Matrix<double, 4, 3> gp;
      if (detail::cell_grad_phi(V, cells, c, gp) == 0.0) detail::throw_degenerate("cell_gradients", c, 4);
      G.row(c) = u(cells(c, 0)) * gp.row(0) + u(cells(c, 1)) * gp.row(1) + u(cells(c, 2)) * gp.row(2) +
                 u(cells(c, 3)) * gp.row(3);
    } else {
      Eigen::Matrix<double, 3, 3> gp;
      if (detail::cell_grad_phi(V, cells, c, gp) == 0.0) detail::throw_degenerate("cell_gradients", c, 3);
      G.row(c) = u(cells(c, 0)) * gp.row(0) + u(cells(c, 1)) * gp.row(1) + u(cells(c, 2)) * gp.row(2);
    }
  }
  return G;
}

Eigen::MatrixXd vertex_gradients(const Eigen::MatrixXd& V, const Eigen::MatrixXi& cells, const Eigen::VectorXd& u) {
  const Eigen::MatrixXd G = cell_gradients(V, cells, u);
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(V.rows(), 3);
  Eigen::VectorXd w = Eigen::VectorXd::Zero(V.rows());
  for (Eigen::Index c = 0; c < cells.rows(); ++c) {
    const double m = detail::cell_measure(V, cells, c);
    for (Eigen::Index k = 0; k < cells.cols(); ++k) {
      out.row(cells(c, k)) += m * G.row(c);
      w(cells(c, k)) += m;
    }
  }
  for (Eigen::Index i = 0; i < V.rows(); ++i)
    if (w(i) > 0) out.row(i) /= w(i);
  return out;
}

}  // namespace igaprep::param
