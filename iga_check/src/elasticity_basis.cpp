#include "elasticity_basis.h"

#include <Eigen/LU>

#include "igaprep/spline/basis.h"
#include "igaprep/spline/gauss_legendre.h"
#include "igaprep/spline/knot_vector.h"

namespace igaprep::iga_check::detail {

std::vector<DirElement> direction_elements(const std::vector<double>& U, int p, const Eigen::VectorXd& gp,
                                           const Eigen::VectorXd& gw) {
  const int n = spline::basis_count(U, p);
  std::vector<DirElement> out;
  for (int s = p; s < n; ++s) {
    const double a = U[s], b = U[s + 1];
    if (!(b > a)) continue;
    DirElement e;
    e.first = s - p;
    for (Eigen::Index q = 0; q < gp.size(); ++q) {
      e.u.push_back(a + (b - a) * gp(q));
      e.w.push_back((b - a) * gw(q));
    }
    // The span is known: no search, and points never land on the wrong side of a knot.
    e.basis = spline::basis_table_on_span(U, p, s, e.u, 1);
    out.push_back(std::move(e));
  }
  return out;
}

DirElement direction_point(const std::vector<double>& U, int p, double u) {
  DirElement e;
  e.u = {u};
  e.w = {1.0};
  e.basis = spline::basis_table(U, p, e.u, 1);
  e.first = e.basis.span[0] - p;
  return e;
}

std::array<std::vector<DirElement>, 3> patch_elements(const spline::Patch& p, int extra) {
  std::array<std::vector<DirElement>, 3> t;
  for (int d = 0; d < 3; ++d) {
    Eigen::VectorXd gp, gw;
    spline::gauss_legendre(p.degrees[d] + 1 + extra, gp, gw);
    t[d] = direction_elements(p.knots[d], p.degrees[d], gp, gw);
  }
  return t;
}

void element_values(const spline::Patch& patch, const DirElement& eu, const DirElement& ev, const DirElement& ew,
                    bool need_grad, ElementValues& o) {
  const int pu = patch.degrees[0], pv = patch.degrees[1], pw = patch.degrees[2];
  const int nu = eu.size(), nv = ev.size(), nw = ew.size();
  const int nq = nu * nv * nw;
  const int n = (pu + 1) * (pv + 1) * (pw + 1);
  const bool rational = patch.rational();

  o.local.resize(n);
  o.X.resize(n, 3);
  o.lw.resize(n);
  for (int iw = 0, a = 0; iw <= pw; ++iw)
    for (int iv = 0; iv <= pv; ++iv)
      for (int iu = 0; iu <= pu; ++iu, ++a) {
        const int l = patch.index(eu.first + iu, ev.first + iv, ew.first + iw);
        o.local[a] = l;
        o.X.row(a) = patch.control_points.row(l);
        o.lw(a) = rational ? patch.weights(l) : 1.0;
      }

  o.R.resize(nq, n);
  o.Du.resize(nq, n);
  o.Dv.resize(nq, n);
  o.Dw.resize(nq, n);
  o.w.resize(nq);
  for (int qw = 0, q = 0; qw < nw; ++qw)
    for (int qv = 0; qv < nv; ++qv)
      for (int qu = 0; qu < nu; ++qu, ++q) {
        o.w(q) = eu.w[qu] * ev.w[qv] * ew.w[qw];
        for (int iw = 0, a = 0; iw <= pw; ++iw) {
          const double Nw = ew.N(qw, iw), dNw = ew.dN(qw, iw);
          for (int iv = 0; iv <= pv; ++iv) {
            const double Nv = ev.N(qv, iv), dNv = ev.dN(qv, iv);
            const double vw = Nv * Nw;
            for (int iu = 0; iu <= pu; ++iu, ++a) {
              const double Nu = eu.N(qu, iu);
              o.R(q, a) = Nu * vw;
              o.Du(q, a) = eu.dN(qu, iu) * vw;
              o.Dv(q, a) = Nu * dNv * Nw;
              o.Dw(q, a) = Nu * Nv * dNw;
            }
          }
        }
      }
  if (rational) {
    // Quotient rule: R_a = w_a B_a / W, dR_a = w_a (dB_a - B_a dW / W) / W.
    const Eigen::VectorXd W = o.R * o.lw;
    const Eigen::VectorXd Wu = o.Du * o.lw, Wv = o.Dv * o.lw, Ww = o.Dw * o.lw;
    for (int q = 0; q < nq; ++q) {
      const double iW = 1.0 / W(q);
      for (int a = 0; a < n; ++a) {
        const double s = o.lw(a) * iW;
        const double B = o.R(q, a);
        o.Du(q, a) = s * (o.Du(q, a) - B * Wu(q) * iW);
        o.Dv(q, a) = s * (o.Dv(q, a) - B * Wv(q) * iW);
        o.Dw(q, a) = s * (o.Dw(q, a) - B * Ww(q) * iW);
        o.R(q, a) = s * B;
      }
    }
  }
  o.x.noalias() = o.R * o.X;
  o.J.resize(nq, 9);
  const Eigen::MatrixXd Pu = o.Du * o.X, Pv = o.Dv * o.X, Pw = o.Dw * o.X;
  o.det.resize(nq);
  if (need_grad) o.grad.resize(nq, 3 * n);
  for (int q = 0; q < nq; ++q) {
    Eigen::Matrix3d J;
    J.col(0) = Pu.row(q).transpose();
    J.col(1) = Pv.row(q).transpose();
    J.col(2) = Pw.row(q).transpose();
    for (int c = 0; c < 3; ++c)
      for (int d = 0; d < 3; ++d) o.J(q, 3 * c + d) = J(c, d);
    o.det(q) = J.determinant();
    if (!need_grad) continue;
    // Row gradients: grad_x R_a = grad_u R_a * J^{-1}.
    const Eigen::Matrix3d Ji = J.inverse();
    for (int c = 0; c < 3; ++c)
      o.grad.block(q, c * n, 1, n) = Ji(0, c) * o.Du.row(q) + Ji(1, c) * o.Dv.row(q) + Ji(2, c) * o.Dw.row(q);
  }
}

}  // namespace igaprep::iga_check::detail
