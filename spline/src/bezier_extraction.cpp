// Bezier extraction operators (Borden, Scott, Evans & Hughes 2011, Algorithm 1):
// the knots of each element are raised to full multiplicity one element at a
// time, recording the insertion coefficients instead of applying them.
#include "igaprep/spline/bezier_extraction.h"

#include "igaprep/core/error.h"
#include "igaprep/spline/basis.h"
#include "igaprep/spline/knot_vector.h"
#include "internal.h"

namespace igaprep::spline {

Extraction1d bezier_extraction_1d(const std::vector<double>& U, int p) {
  Extraction1d ex;
  ex.degree = p;
  const int m = static_cast<int>(U.size());
  const int n = basis_count(U, p);
  if (n < p + 1) throw bad_input("bezier_extraction: knot vector too short for the degree");
  std::vector<double> alphas(p + 1);
  int a = p, b = a + 1;
  ex.C.push_back(Eigen::MatrixXd::Identity(p + 1, p + 1));
  ex.breaks.push_back(U[p]);
  ex.first.push_back(0);
  while (b < m - p - 1 + 1 && b <= n) {  // b walks the knots after U[a] up to U[n]
    // Next distinct knot and its multiplicity (only knots up to U[n] matter).
    const int i = b;
    while (b < n && U[b + 1] == U[b]) ++b;
    const int mult = b - i + 1;
    const bool last = (b >= n);
    if (!last) ex.C.push_back(Eigen::MatrixXd::Identity(p + 1, p + 1));
    Eigen::MatrixXd& Cc = ex.C[ex.C.size() - (last ? 1 : 2)];
    if (mult < p && !last) {
      const double numer = U[b] - U[a];
      for (int j = p; j > mult; --j) alphas[j - mult - 1] = numer / (U[a + j] - U[a]);
      const int r = p - mult;
      Eigen::MatrixXd& Cn = ex.C.back();
      for (int j = 1; j <= r; ++j) {
        const int save = r - j, s = mult + j;
        for (int k = p; k >= s; --k) {
          const double al = alphas[k - s];
          Cc.col(k) = al * Cc.col(k) + (1.0 - al) * Cc.col(k - 1);
        }
        Cn.block(save, save, j + 1, 1) = Cc.block(p - j, p, j + 1, 1);
      }
    }
    ex.breaks.push_back(U[b]);
    if (last) break;
    a = b;
    b = a + 1;
    ex.first.push_back(a - p);
  }
  return ex;
}

PatchExtraction bezier_extraction(const Patch& p) {
  PatchExtraction ex;
  for (int d = 0; d < 3; ++d) ex.dirs[d] = bezier_extraction_1d(p.knots[d], p.degrees[d]);
  return ex;
}

Eigen::MatrixXd element_extraction_operator(const PatchExtraction& ex, int eu, int ev, int ew) {
  const Eigen::MatrixXd &Cu = ex.dirs[0].C.at(eu), &Cv = ex.dirs[1].C.at(ev), &Cw = ex.dirs[2].C.at(ew);
  const int a = static_cast<int>(Cu.rows()), b = static_cast<int>(Cv.rows()), c = static_cast<int>(Cw.rows());
  Eigen::MatrixXd K(a * b * c, a * b * c);
  for (int kw = 0; kw < c; ++kw)
    for (int kv = 0; kv < b; ++kv)
      for (int ku = 0; ku < a; ++ku) {
        const int row = ku + a * (kv + b * kw);
        for (int lw = 0; lw < c; ++lw)
          for (int lv = 0; lv < b; ++lv) {
            const double f = Cw(kw, lw) * Cv(kv, lv);
            for (int lu = 0; lu < a; ++lu) K(row, lu + a * (lv + b * lw)) = f * Cu(ku, lu);
          }
      }
  return K;
}

std::vector<int> element_control_points(const Patch& p, const PatchExtraction& ex, int eu, int ev, int ew) {
  const int f0 = ex.dirs[0].first.at(eu), f1 = ex.dirs[1].first.at(ev), f2 = ex.dirs[2].first.at(ew);
  std::vector<int> idx;
  idx.reserve(static_cast<size_t>(p.degrees[0] + 1) * (p.degrees[1] + 1) * (p.degrees[2] + 1));
  for (int k = 0; k <= p.degrees[2]; ++k)
    for (int j = 0; j <= p.degrees[1]; ++j)
      for (int i = 0; i <= p.degrees[0]; ++i) idx.push_back(p.index(f0 + i, f1 + j, f2 + k));
  return idx;
}

BezierElement bezier_element_from(const Eigen::MatrixXd& C, const Eigen::MatrixXd& H) {
  const Eigen::MatrixXd Hb = C.transpose() * H;
  BezierElement e;
  if (H.cols() == 4) {
    e.weights = Hb.col(3);
    e.points = Hb.leftCols<3>().array().colwise() / e.weights.array();
  } else {
    e.points = Hb;
  }
  return e;
}

BezierElement bernstein_control_points(const Patch& p, const PatchExtraction& ex, int eu, int ev, int ew) {
  const std::vector<int> idx = element_control_points(p, ex, eu, ev, ew);
  const Eigen::MatrixXd H = detail::homogeneous_points(p);
  Eigen::MatrixXd local(static_cast<long>(idx.size()), H.cols());
  for (size_t i = 0; i < idx.size(); ++i) local.row(i) = H.row(idx[i]);
  BezierElement e = bezier_element_from(element_extraction_operator(ex, eu, ev, ew), local);
  const int el[3] = {eu, ev, ew};
  for (int d = 0; d < 3; ++d) e.domain[d] = {{ex.dirs[d].breaks[el[d]], ex.dirs[d].breaks[el[d] + 1]}};
  return e;
}

Eigen::Vector3d evaluate_bezier(const BezierElement& e, const std::array<int, 3>& deg, const Eigen::Vector3d& t) {
  double B[3][32];
  for (int d = 0; d < 3; ++d) bernstein_basis(deg[d], t[d], B[d]);
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  double W = 0;
  const bool rat = e.weights.size() > 0;
  int q = 0;
  for (int k = 0; k <= deg[2]; ++k)
    for (int j = 0; j <= deg[1]; ++j)
      for (int i = 0; i <= deg[0]; ++i, ++q) {
        const double f = B[0][i] * B[1][j] * B[2][k] * (rat ? e.weights[q] : 1.0);
        x += f * e.points.row(q).transpose();
        W += f;
      }
  return rat ? Eigen::Vector3d(x / W) : x;
}

}  // namespace igaprep::spline
