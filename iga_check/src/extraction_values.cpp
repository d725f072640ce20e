#include "extraction_values.h"

#include <vector>

#include "igaprep/spline/basis.h"

namespace igaprep::iga_check::detail {

Eigen::MatrixXd bernstein_table(int p, const Eigen::VectorXd& t, int order) {
  Eigen::MatrixXd out(p + 1, t.size());
  std::vector<double> B(static_cast<std::size_t>(p) + 1), L(static_cast<std::size_t>(p));
  for (Eigen::Index q = 0; q < t.size(); ++q) {
    spline::bernstein_basis(p, t[q], B.data());
    if (order == 0) {
      for (int k = 0; k <= p; ++k) out(k, q) = B[static_cast<std::size_t>(k)];
      continue;
    }
    // d/dt B_k^p = p (B_{k-1}^{p-1} - B_k^{p-1})
    if (p > 0) spline::bernstein_basis(p - 1, t[q], L.data());
    for (int k = 0; k <= p; ++k) {
      const double left = k > 0 ? L[static_cast<std::size_t>(k - 1)] : 0.0, right = k < p ? L[static_cast<std::size_t>(k)] : 0.0;
      out(k, q) = p > 0 ? p * (left - right) : 0.0;
    }
  }
  return out;
}

ExtractionValues extraction_values(const spline::ExtractionModel& m, int element, const std::array<Eigen::VectorXd, 3>& t) {
  const spline::ExtractionElement& e = m.elements[static_cast<std::size_t>(element)];
  std::array<Eigen::MatrixXd, 3> B, D;
  for (std::size_t d = 0; d < 3; ++d) {
    B[d] = bernstein_table(e.degrees[d], t[d], 0);
    D[d] = bernstein_table(e.degrees[d], t[d], 1);
  }
  const Eigen::Index nu = t[0].size(), nv = t[1].size(), nw = t[2].size(), nq = nu * nv * nw;
  const Eigen::Index pu = e.degrees[0] + 1, pv = e.degrees[1] + 1, pw = e.degrees[2] + 1, nb = pu * pv * pw;
  // Tensor Bernstein values and t-derivatives: nb x nq.
  Eigen::MatrixXd TB(nb, nq), TD[3] = {Eigen::MatrixXd(nb, nq), Eigen::MatrixXd(nb, nq), Eigen::MatrixXd(nb, nq)};
  for (Eigen::Index c = 0; c < nw; ++c)
    for (Eigen::Index b = 0; b < nv; ++b)
      for (Eigen::Index a = 0; a < nu; ++a) {
        const Eigen::Index q = a + nu * (b + nv * c);
        for (Eigen::Index k = 0; k < pw; ++k)
          for (Eigen::Index j = 0; j < pv; ++j)
            for (Eigen::Index i = 0; i < pu; ++i) {
              const Eigen::Index r = i + pu * (j + pv * k);
              TB(r, q) = B[0](i, a) * B[1](j, b) * B[2](k, c);
              TD[0](r, q) = D[0](i, a) * B[1](j, b) * B[2](k, c);
              TD[1](r, q) = B[0](i, a) * D[1](j, b) * B[2](k, c);
              TD[2](r, q) = B[0](i, a) * B[1](j, b) * D[2](k, c);
            }
      }
  const Eigen::MatrixXd& C = m.C(element);
  const Eigen::Index n = static_cast<Eigen::Index>(e.functions.size());
  Eigen::VectorXd w(n);
  Eigen::MatrixXd P(3, n);
  for (Eigen::Index f = 0; f < n; ++f) {
    w[f] = m.weights[e.functions[static_cast<std::size_t>(f)]];
    P.col(f) = m.control_points.row(e.functions[static_cast<std::size_t>(f)]).transpose();
  }
  // Rational basis R = w N / W and its derivatives.
  const Eigen::MatrixXd N = w.asDiagonal() * (C * TB);
  const Eigen::RowVectorXd W = N.colwise().sum();
  ExtractionValues out;
  out.R = N * W.cwiseInverse().asDiagonal();
  for (std::size_t d = 0; d < 3; ++d) {
    const Eigen::MatrixXd dN = w.asDiagonal() * (C * TD[d]);
    const Eigen::RowVectorXd dW = dN.colwise().sum();
    out.dR[d] = (dN - out.R * dW.asDiagonal()) * W.cwiseInverse().asDiagonal();
  }
  out.x = P * out.R;
  out.J.resize(static_cast<std::size_t>(nq));
  for (Eigen::Index q = 0; q < nq; ++q)
    for (int d = 0; d < 3; ++d) out.J[static_cast<std::size_t>(q)].col(d) = P * out.dR[static_cast<std::size_t>(d)].col(q);
  return out;
}

}  // namespace igaprep::iga_check::detail
