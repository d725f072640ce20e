// Knot insertion (Piegl & Tiller A5.4, on whole coefficient rows) and degree
// elevation (Bezier decomposition, elevation of each Bezier segment, then
// exact removal of the knots back to their old multiplicity + t). Volumes are
// processed direction by direction in homogeneous coordinates.
#include "igaprep/spline/refine.h"

#include <algorithm>
#include <iterator>
#include <cmath>
#include <sstream>

#include "igaprep/core/error.h"
#include "igaprep/spline/knot_removal.h"
#include "igaprep/spline/knot_vector.h"
#include "internal.h"

namespace igaprep::spline {

void insert_knots_1d(const std::vector<double>& U, int p, const Eigen::MatrixXd& P,
                     const std::vector<double>& Xin, std::vector<double>* U_new, Eigen::MatrixXd* P_new) {
  const int ncount = basis_count(U, p);
  if (P.rows() != ncount) throw bad_input("insert_knots: coefficient rows do not match the knot vector");
  if (Xin.empty()) {
    *U_new = U;
    *P_new = P;
    return;
  }
  std::vector<double> X = Xin;
  std::sort(X.begin(), X.end());
  for (double x : X) {
    if (!(x > U[p] && x < U[ncount])) {
      std::ostringstream s;
      s << "insert_knots: knot " << x << " is not inside the parameter domain (" << U[p] << ", "
        << U[ncount] << ")";
      throw bad_input(s.str());
    }
    const int mult = knot_multiplicity(U, x) + static_cast<int>(std::count(X.begin(), X.end(), x));
    if (mult > p) {
      std::ostringstream s;
      s << "insert_knots: knot " << x << " would reach multiplicity " << mult << " > degree " << p;
      throw bad_input(s.str());
    }
  }
  const int n = ncount - 1, m = n + p + 1, r = static_cast<int>(X.size()) - 1;
  const int a = find_span(U, p, X[0]);
  const int b = find_span(U, p, X[r]) + 1;
  Eigen::MatrixXd Q(ncount + r + 1, P.cols());
  std::vector<double> Ub(U.size() + X.size());
  for (int j = 0; j <= a - p; ++j) Q.row(j) = P.row(j);
  for (int j = b - 1; j <= n; ++j) Q.row(j + r + 1) = P.row(j);
  for (int j = 0; j <= a; ++j) Ub[j] = U[j];
  for (int j = b + p; j <= m; ++j) Ub[j + r + 1] = U[j];
  int i = b + p - 1, k = b + p + r;
  for (int j = r; j >= 0; --j) {
    while (X[j] <= U[i] && i > a) {
      Q.row(k - p - 1) = P.row(i - p - 1);
      Ub[k] = U[i];
      --k;
      --i;
    }
    Q.row(k - p - 1) = Q.row(k - p);
    for (int l = 1; l <= p; ++l) {
      const int ind = k - p + l;
      double alfa = Ub[k + l] - X[j];
      if (alfa == 0.0) {
        Q.row(ind - 1) = Q.row(ind);
      } else {
        alfa /= (Ub[k + l] - U[i - p + l]);
        Q.row(ind - 1) = alfa * Q.row(ind - 1) + (1.0 - alfa) * Q.row(ind);
      }
    }
    Ub[k] = X[j];
    --k;
  }
  *U_new = std::move(Ub);
  *P_new = std::move(Q);
}

namespace {
double binom(int n, int k) {
  if (k < 0 || k > n) return 0.0;
  double r = 1.0;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}
}  // namespace

void elevate_degree_1d(const std::vector<double>& U, int p, const Eigen::MatrixXd& P, int t,
                       std::vector<double>* U_new, Eigen::MatrixXd* P_new) {
  if (t < 0) throw bad_input("elevate_degree: negative elevation");
  if (p + t > 30) throw bad_input("elevate_degree: degree would exceed 30");
  if (t == 0) {
    *U_new = U;
    *P_new = P;
    return;
  }
  const std::vector<double> breaks = unique_knots(U);
  const int ne = static_cast<int>(breaks.size()) - 1;
  // 1. Bezier decomposition: every interior knot to multiplicity p.
  std::vector<double> X;
  std::vector<int> old_mult(ne + 1, 0);
  for (int e = 1; e < ne; ++e) {
    old_mult[e] = knot_multiplicity(U, breaks[e]);
    for (int k = old_mult[e]; k < p; ++k) X.push_back(breaks[e]);
  }
  std::vector<double> Ub;
  Eigen::MatrixXd Pb;
  if (p == 0) {
    // Piecewise constants: each segment is its own Bezier piece already.
    Ub = U;
    Pb = P;
  } else {
    insert_knots_1d(U, p, P, X, &Ub, &Pb);
  }
  // 2. Elevate each Bezier segment: Q_i = sum_j C(p,j) C(t,i-j) / C(p+t,i) P_j.
  const int q = p + t;
  Eigen::MatrixXd E((p == 0 ? ne * (q + 1) : ne * q + 1), P.cols());
  Eigen::MatrixXd coef(q + 1, p + 1);
  for (int i = 0; i <= q; ++i)
    for (int j = 0; j <= p; ++j) coef(i, j) = binom(p, j) * binom(t, i - j) / binom(q, i);
  for (int e = 0; e < ne; ++e) {
    const int src = (p == 0) ? e : e * p;
    const int dst = (p == 0) ? e * (q + 1) : e * q;
    E.middleRows(dst, q + 1) = coef * Pb.middleRows(src, p + 1);
  }
  std::vector<double> Ue(q + 1, breaks.front());
  for (int e = 1; e < ne; ++e) Ue.insert(Ue.end(), (p == 0) ? q + 1 : q, breaks[e]);
  Ue.insert(Ue.end(), q + 1, breaks.back());
  // 3. Remove each interior knot back to multiplicity old + t (exact up to round-off).
  for (int e = 1; e < ne; ++e) {
    const int target = old_mult[e] + t;
    int have = knot_multiplicity(Ue, breaks[e]);
    while (have > target) {
      const int r = static_cast<int>(std::upper_bound(Ue.begin(), Ue.end(), breaks[e]) - Ue.begin()) - 1;
      std::vector<double> Un;
      Eigen::MatrixXd Pn;
      remove_knot_once_1d(Ue, q, E, r, static_cast<int>(E.cols()), &Un, &Pn);
      Ue = std::move(Un);
      E = std::move(Pn);
      --have;
    }
  }
  *U_new = std::move(Ue);
  *P_new = std::move(E);
}

Eigen::MatrixXd patch_rows(const Patch& patch, int dir) {
  const Eigen::MatrixXd H = detail::homogeneous_points(patch);
  const int D = static_cast<int>(H.cols());
  const int n[3] = {patch.count(0), patch.count(1), patch.count(2)};
  const int a = (dir == 0) ? 1 : 0, b = (dir == 2) ? 1 : 2;
  Eigen::MatrixXd R(n[dir], static_cast<long>(n[a]) * n[b] * D);
  int ijk[3];
  for (ijk[2] = 0; ijk[2] < n[2]; ++ijk[2])
    for (ijk[1] = 0; ijk[1] < n[1]; ++ijk[1])
      for (ijk[0] = 0; ijk[0] < n[0]; ++ijk[0]) {
        const long col = (ijk[a] + static_cast<long>(n[a]) * ijk[b]) * D;
        const int g = patch.index(ijk[0], ijk[1], ijk[2]);
        for (int c = 0; c < D; ++c) R(ijk[dir], col + c) = H(g, c);
      }
  return R;
}

void set_patch_rows(Patch* patch, int dir, const Eigen::MatrixXd& R, int n_dir) {
  const int a = (dir == 0) ? 1 : 0, b = (dir == 2) ? 1 : 2;
  int n[3] = {patch->count(0), patch->count(1), patch->count(2)};
  n[dir] = n_dir;
  const long others = static_cast<long>(n[a]) * n[b];
  if (R.rows() != n_dir || R.cols() % others != 0)
    throw internal_error("set_patch_rows: row matrix does not match the patch");
  const int D = static_cast<int>(R.cols() / others);
  Eigen::MatrixXd H(static_cast<long>(n[0]) * n[1] * n[2], D);
  int ijk[3];
  for (ijk[2] = 0; ijk[2] < n[2]; ++ijk[2])
    for (ijk[1] = 0; ijk[1] < n[1]; ++ijk[1])
      for (ijk[0] = 0; ijk[0] < n[0]; ++ijk[0]) {
        const long col = (ijk[a] + static_cast<long>(n[a]) * ijk[b]) * D;
        const long g = ijk[0] + static_cast<long>(n[0]) * (ijk[1] + static_cast<long>(n[1]) * ijk[2]);
        for (int c = 0; c < D; ++c) H(g, c) = R(ijk[dir], col + c);
      }
  detail::set_from_homogeneous(H, patch);
}

namespace {
void check_dir(int dir) {
  if (dir < 0 || dir > 2) throw bad_input("refinement: direction must be 0, 1 or 2");
}
}  // namespace

Patch insert_knots(const Patch& patch, int dir, const std::vector<double>& X) {
  check_dir(dir);
  Patch out = patch;
  std::vector<double> Un;
  Eigen::MatrixXd R;
  insert_knots_1d(patch.knots[dir], patch.degrees[dir], patch_rows(patch, dir), X, &Un, &R);
  out.knots[dir] = Un;
  set_patch_rows(&out, dir, R, static_cast<int>(R.rows()));
  if (out.displacement.size() > 0) out.displacement.resize(0, 0);  // no longer matches the basis
  return out;
}

Patch insert_knot(const Patch& patch, int dir, double u, int times) {
  return insert_knots(patch, dir, std::vector<double>(std::max(0, times), u));
}

Patch elevate_degree(const Patch& patch, int dir, int t) {
  check_dir(dir);
  Patch out = patch;
  std::vector<double> Un;
  Eigen::MatrixXd R;
  elevate_degree_1d(patch.knots[dir], patch.degrees[dir], patch_rows(patch, dir), t, &Un, &R);
  out.knots[dir] = Un;
  out.degrees[dir] = patch.degrees[dir] + t;
  set_patch_rows(&out, dir, R, static_cast<int>(R.rows()));
  if (out.displacement.size() > 0) out.displacement.resize(0, 0);
  return out;
}

std::vector<double> missing_knots(const std::vector<double>& fine, const std::vector<double>& coarse) {
  std::vector<double> missing, extra;
  std::set_difference(fine.begin(), fine.end(), coarse.begin(), coarse.end(), std::back_inserter(missing));
  std::set_difference(coarse.begin(), coarse.end(), fine.begin(), fine.end(), std::back_inserter(extra));
  if (!extra.empty() || coarse.empty() || fine.empty() || coarse.front() != fine.front() || coarse.back() != fine.back())
    throw bad_input("refinement: a knot vector is not nested in the finer one");
  return missing;
}

Patch refine_to_knots(const Patch& patch, const std::array<std::vector<double>, 3>& knots) {
  Patch out = patch;
  for (int d = 0; d < 3; ++d) {
    const std::vector<double> X = missing_knots(knots[d], out.knots[d]);
    if (!X.empty()) out = insert_knots(out, d, X);
  }
  return out;
}

Patch refine_uniformly(const Patch& patch, int k) {
  Patch out = patch;
  for (int d = 0; d < 3; ++d) {
    const std::vector<double> br = unique_knots(patch.knots[d]);
    std::vector<double> X;
    for (size_t e = 0; e + 1 < br.size(); ++e)
      for (int i = 1; i <= k; ++i) X.push_back(br[e] + (br[e + 1] - br[e]) * i / (k + 1));
    out = insert_knots(out, d, X);
  }
  return out;
}

Surface insert_knots(const Surface& s, int dir, const std::vector<double>& X) {
  if (dir < 0 || dir > 1) throw bad_input("refinement: surface direction must be 0 or 1");
  const Patch p = insert_knots(as_patch(s), dir, X);
  Surface o = s;
  o.knots[dir] = p.knots[dir];
  o.control_points = p.control_points;
  o.weights = p.weights;
  return o;
}
Surface elevate_degree(const Surface& s, int dir, int t) {
  if (dir < 0 || dir > 1) throw bad_input("refinement: surface direction must be 0 or 1");
  const Patch p = elevate_degree(as_patch(s), dir, t);
  Surface o = s;
  o.knots[dir] = p.knots[dir];
  o.degrees[dir] = p.degrees[dir];
  o.control_points = p.control_points;
  o.weights = p.weights;
  return o;
}
Curve insert_knots(const Curve& c, const std::vector<double>& X) {
  const Patch p = insert_knots(as_patch(c), 0, X);
  Curve o = c;
  o.knots = p.knots[0];
  o.control_points = p.control_points;
  o.weights = p.weights;
  return o;
}
Curve elevate_degree(const Curve& c, int t) {
  const Patch p = elevate_degree(as_patch(c), 0, t);
  Curve o = c;
  o.knots = p.knots[0];
  o.degree = p.degrees[0];
  o.control_points = p.control_points;
  o.weights = p.weights;
  return o;
}

}  // namespace igaprep::spline
