// VTU Bezier writer. Geometry from spline::bezier_extraction; the stress uses
// spline::evaluate_jacobian on the geometry and on the displacement (as a
// patch with the same basis), so no evaluation code is duplicated here.
#include "igaprep/export/vtu_bezier.h"

#include <Eigen/LU>
#include <algorithm>
#include <type_traits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "igaprep/core/atomic_file.h"
#include "igaprep/core/error.h"
#include "igaprep/spline/basis.h"
#include "igaprep/spline/bezier_extraction.h"
#include "igaprep/spline/evaluate.h"
#include "model_checks.h"
#include "number_text.h"
#include "vtu_arrays.h"
#include "vtu_grid.h"

namespace igaprep::exporter {

int vtk_hex_point_index(int i, int j, int k, const std::array<int, 3>& order) {
  const bool ibdy = (i == 0 || i == order[0]);
  const bool jbdy = (j == 0 || j == order[1]);
  const bool kbdy = (k == 0 || k == order[2]);
  const int nbdy = (ibdy ? 1 : 0) + (jbdy ? 1 : 0) + (kbdy ? 1 : 0);
  if (nbdy == 3) return (i ? (j ? 2 : 1) : (j ? 3 : 0)) + (k ? 4 : 0);  // corner
  int offset = 8;
  if (nbdy == 2) {  // edge
    if (!ibdy) return (i - 1) + (j ? order[0] + order[1] - 2 : 0) + (k ? 2 * (order[0] + order[1] - 2) : 0) + offset;
    if (!jbdy)
      return (j - 1) + (i ? order[0] - 1 : 2 * (order[0] - 1) + order[1] - 1) +
             (k ? 2 * (order[0] + order[1] - 2) : 0) + offset;
    offset += 4 * (order[0] - 1) + 4 * (order[1] - 1);
    return (k - 1) + (order[2] - 1) * (i ? (j ? 2 : 1) : (j ? 3 : 0)) + offset;
  }
  offset += 4 * (order[0] + order[1] + order[2] - 3);
  if (nbdy == 1) {  // face
    if (ibdy) return (j - 1) + (order[1] - 1) * (k - 1) + (i ? (order[1] - 1) * (order[2] - 1) : 0) + offset;
    offset += 2 * (order[1] - 1) * (order[2] - 1);
    if (jbdy) return (i - 1) + (order[0] - 1) * (k - 1) + (j ? (order[2] - 1) * (order[0] - 1) : 0) + offset;
    offset += 2 * (order[2] - 1) * (order[0] - 1);
    return (i - 1) + (order[0] - 1) * (j - 1) + (k ? (order[0] - 1) * (order[1] - 1) : 0) + offset;
  }
  offset += 2 * ((order[1] - 1) * (order[2] - 1) + (order[2] - 1) * (order[0] - 1) + (order[0] - 1) * (order[1] - 1));
  return offset + (i - 1) + (order[0] - 1) * ((j - 1) + (order[1] - 1) * (k - 1));
}

namespace {
using detail::Grid;


double von_mises(const Eigen::Matrix3d& grad_u, double E, double nu) {
  const Eigen::Matrix3d eps = 0.5 * (grad_u + grad_u.transpose());
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const Eigen::Matrix3d s = lambda * eps.trace() * Eigen::Matrix3d::Identity() + 2 * mu * eps;
  const double d01 = s(0, 0) - s(1, 1), d12 = s(1, 1) - s(2, 2), d20 = s(2, 2) - s(0, 0);
  return std::sqrt(0.5 * (d01 * d01 + d12 * d12 + d20 * d20) +
                   3.0 * (s(0, 1) * s(0, 1) + s(1, 2) * s(1, 2) + s(0, 2) * s(0, 2)));
}

// Inverse of the 1-D Bernstein collocation matrix at t = i/p: M(i, b) = B_b(i/p).
Eigen::MatrixXd bernstein_node_inverse(int p) {
  Eigen::MatrixXd M(p + 1, p + 1);
  std::vector<double> B(p + 1);
  for (int i = 0; i <= p; ++i) {
    spline::bernstein_basis(p, static_cast<double>(i) / p, B.data());
    for (int b = 0; b <= p; ++b) M(i, b) = B[b];
  }
  return M.inverse();
}

void build_grid(const spline::MultiPatch& model, Grid& g) {
  const bool solution = std::any_of(model.patches.begin(), model.patches.end(),
                                    [](const spline::Patch& p) { return p.displacement.size() > 0; });
  for (size_t pi = 0; pi < model.patches.size(); ++pi) {
    const spline::Patch& p = model.patches[pi];
    const std::array<int, 3> deg = p.degrees;
    for (int d = 0; d < 3; ++d)
      if (deg[d] < 1)
        throw bad_input("VTU Bezier: patch " + std::to_string(pi) + " has degree 0 in direction " +
                        detail::direction_name(d) + " (VTK Bezier cells need degree >= 1)");
    const int nb = (deg[0] + 1) * (deg[1] + 1) * (deg[2] + 1);
    const std::vector<int> vtk_of_local = detail::vtk_hex_order(deg);
    const spline::PatchExtraction ex = spline::bezier_extraction(p);
    const bool has_u = p.displacement.size() > 0;
    spline::Patch disp;  // the displacement as a patch in the same basis
    std::array<Eigen::MatrixXd, 3> node_inv;
    if (has_u) {
      disp = p;
      disp.control_points = p.displacement;
      disp.displacement.resize(0, 0);
      for (int d = 0; d < 3; ++d) node_inv[d] = bernstein_node_inverse(deg[d]);
    }
    const spline::Material& mat = model.materials[p.material];
    const std::vector<double> min_scaled_jacobian = detail::element_min_scaled_jacobians(p);
    for (int ew = 0; ew < ex.element_count(2); ++ew)
      for (int ev = 0; ev < ex.element_count(1); ++ev)
        for (int eu = 0; eu < ex.element_count(0); ++eu) {
          // Bernstein points C^T P (homogeneous). spline::bernstein_control_points
          // gives the same but rebuilds the patch's homogeneous points per call.
          const Eigen::MatrixXd C = spline::element_extraction_operator(ex, eu, ev, ew);
          const std::vector<int> local = spline::element_control_points(p, ex, eu, ev, ew);
          Eigen::MatrixXd hp(local.size(), p.rational() ? 4 : 3);
          for (size_t r = 0; r < local.size(); ++r) {
            if (p.rational())
              hp.row(r) << p.control_points.row(local[r]) * p.weights[local[r]], p.weights[local[r]];
            else
              hp.row(r) = p.control_points.row(local[r]);
          }
          spline::BezierElement be = spline::bezier_element_from(C, hp);
          const int el[3] = {eu, ev, ew};
          for (int d = 0; d < 3; ++d) be.domain[d] = {{ex.dirs[d].breaks[el[d]], ex.dirs[d].breaks[el[d] + 1]}};
          const int64_t base = detail::add_cell(g, be, vtk_of_local, deg, p.material, static_cast<int>(pi), {{eu, ev, ew}},
                                                min_scaled_jacobian[static_cast<std::size_t>(
                                                    eu + ex.element_count(0) * (ev + ex.element_count(1) * ew))]);
          if (!solution) continue;
          g.displacement.resize(g.displacement.size() + 3 * nb, 0.0);
          g.von_mises.resize(g.von_mises.size() + nb, 0.0);
          if (!has_u) continue;
          // Displacement: Bernstein coefficients, homogeneous like the geometry.
          Eigen::MatrixXd hu(local.size(), 3);
          for (size_t r = 0; r < local.size(); ++r)
            hu.row(r) = p.displacement.row(local[r]) * (p.rational() ? p.weights[local[r]] : 1.0);
          const Eigen::MatrixXd bu = C.transpose() * hu;
          // von Mises at the nodes, times the element's weight function W
          // there, then the tensor inverse of the node collocation gives the
          // homogeneous Bernstein coefficients (c_b w_b).
          Eigen::VectorXd rhs(nb);
          for (int k = 0; k <= deg[2]; ++k)
            for (int j = 0; j <= deg[1]; ++j)
              for (int i = 0; i <= deg[0]; ++i) {
                const Eigen::Vector3d t(static_cast<double>(i) / deg[0], static_cast<double>(j) / deg[1],
                                        static_cast<double>(k) / deg[2]);
                Eigen::Vector3d xi;
                for (int d = 0; d < 3; ++d) xi[d] = be.domain[d][0] + t[d] * (be.domain[d][1] - be.domain[d][0]);
                const Eigen::Matrix3d Jx = spline::evaluate_jacobian(p, xi);
                const Eigen::Matrix3d Ju = spline::evaluate_jacobian(disp, xi);
                const double s = von_mises(Ju * Jx.inverse(), mat.young_modulus, mat.poisson_ratio);
                double W = 1.0;
                if (p.rational()) {
                  W = 0.0;
                  std::vector<double> Bu(deg[0] + 1), Bv(deg[1] + 1), Bw(deg[2] + 1);
                  spline::bernstein_basis(deg[0], t[0], Bu.data());
                  spline::bernstein_basis(deg[1], t[1], Bv.data());
                  spline::bernstein_basis(deg[2], t[2], Bw.data());
                  for (int c = 0; c <= deg[2]; ++c)
                    for (int b = 0; b <= deg[1]; ++b)
                      for (int a = 0; a <= deg[0]; ++a)
                        W += Bu[a] * Bv[b] * Bw[c] * be.weights[a + (deg[0] + 1) * (b + (deg[1] + 1) * c)];
                }
                rhs[i + (deg[0] + 1) * (j + (deg[1] + 1) * k)] = s * W;
              }
          // Apply inv(M_u), inv(M_v), inv(M_w) along each direction.
          Eigen::VectorXd hc = rhs;
          const int n[3] = {deg[0] + 1, deg[1] + 1, deg[2] + 1};
          const int stride[3] = {1, n[0], n[0] * n[1]};
          for (int d = 0; d < 3; ++d) {
            Eigen::VectorXd next = Eigen::VectorXd::Zero(nb);
            for (int idx = 0; idx < nb; ++idx) {
              const int pos = (idx / stride[d]) % n[d];
              const int line = idx - pos * stride[d];
              for (int q = 0; q < n[d]; ++q) next[idx] += node_inv[d](pos, q) * hc[line + q * stride[d]];
            }
            hc = next;
          }
          for (int b = 0; b < nb; ++b) {
            const double w = p.rational() ? be.weights[b] : 1.0;
            const int64_t at = base + vtk_of_local[b];
            for (int c = 0; c < 3; ++c) g.displacement[3 * at + c] = bu(b, c) / w;
            g.von_mises[at] = hc[b] / w;
          }
        }
  }
}

}  // namespace

void write_vtu_bezier(const spline::MultiPatch& model, std::ostream& out, const VtuOptions& options) {
  detail::check_model_for_writing(model, "VTU Bezier");
  Grid g;
  build_grid(model, g);
  const bool solution = !g.von_mises.empty();
  if (!solution) detail::share_coincident_points(g);
  const size_t ncells = g.offsets.size();
  if (!options.certified_lower_bound.empty() && options.certified_lower_bound.size() != ncells)
    throw bad_input("VTU Bezier: " + std::to_string(options.certified_lower_bound.size()) +
                    " certified bounds for " + std::to_string(ncells) + " elements");
  detail::write_grid(out, g, options);
}

void write_vtu_bezier(const spline::MultiPatch& model, const std::string& path, const VtuOptions& options) {
  detail::check_model_for_writing(model, "'" + path + "'");
  write_file_atomically(path, [&](std::ostream& out) { write_vtu_bezier(model, out, options); }, true);
}

}  // namespace igaprep::exporter
