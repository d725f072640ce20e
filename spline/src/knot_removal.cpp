// Knot removal (after Tiller / Piegl & Tiller A5.8), on whole coefficient rows
// so that a volume loses a knot of one direction across all its rows at once.
//
// Removing u = U[r] (multiplicity s) once: re-inserting u into the new knot
// vector must give back the old rows Q; the p - s unknown rows follow from the
// insertion equations solved from the left for the first half and from the
// right for the second. The error is then measured exactly by re-inserting u
// and comparing with Q.
//
// Bound on the geometric change. B-spline: both patches are expressed in the
// old basis, so |x - x'| <= max_i |Q_i - Q'_i| (partition of unity,
// non-negativity). NURBS, with homogeneous A = w (x - c) about a centre c:
// x - x' = (dA + (x' - c) dW) / W, so |x - x'| <= (max|dA_i| + R max|dW_i|) / w_min
// with R = max_i |P'_i - c| over the new volume's control points in the old
// basis (x' lies in their convex hull) and w_min the smallest old weight.
#include "igaprep/spline/knot_removal.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "igaprep/core/error.h"
#include "igaprep/spline/knot_vector.h"
#include "igaprep/spline/refine.h"
#include "internal.h"

namespace igaprep::spline {

namespace {

// Removes U[r] once; outputs the new knots/rows and the old-basis re-insertion.
void remove_once(const std::vector<double>& U, int p, const Eigen::MatrixXd& Q, int r,
                 std::vector<double>* U_new, Eigen::MatrixXd* P_new, Eigen::MatrixXd* Q_again) {
  const int n = basis_count(U, p);
  if (r <= p || r >= n) throw bad_input("remove_knot: knot index is not an interior knot");
  const double u = U[r];
  if (U[r + 1] == u) throw internal_error("remove_knot: r must index the last copy of the knot");
  const int s = knot_multiplicity(U, u);
  std::vector<double> Un(U);
  Un.erase(Un.begin() + r);
  const int first = r - p, last = r - s;  // equations first..last, unknowns first..last-1
  Eigen::MatrixXd P(n - 1, Q.cols());
  for (int i = 0; i < first; ++i) P.row(i) = Q.row(i);
  for (int i = last; i < n - 1; ++i) P.row(i) = Q.row(i + 1);
  auto alpha = [&](int i) { return (u - Un[i]) / (Un[i + p] - Un[i]); };
  const int h = last - first;
  const int L = (h + 1) / 2;
  for (int i = first; i < first + L; ++i) {
    const double a = alpha(i);
    P.row(i) = (Q.row(i) - (1.0 - a) * P.row(i - 1)) / a;
  }
  for (int i = last; i >= first + L + 1; --i) {
    const double a = alpha(i);
    P.row(i - 1) = (Q.row(i) - a * P.row(i)) / (1.0 - a);
  }
  std::vector<double> Uq;
  insert_knots_1d(Un, p, P, {u}, &Uq, Q_again);
  *U_new = std::move(Un);
  *P_new = std::move(P);
}

}  // namespace

double remove_knot_once_1d(const std::vector<double>& U, int p, const Eigen::MatrixXd& P, int r,
                           int block, std::vector<double>* U_new, Eigen::MatrixXd* P_new) {
  Eigen::MatrixXd Qa;
  remove_once(U, p, P, r, U_new, P_new, &Qa);
  if (block <= 0 || P.cols() % block != 0) throw bad_input("remove_knot: bad block width");
  double err = 0;
  const Eigen::MatrixXd dQ = Qa - P;
  for (long i = 0; i < dQ.rows(); ++i)
    for (long c = 0; c < dQ.cols(); c += block) err = std::max(err, dQ.row(i).segment(c, block).norm());
  return err;
}

double change_bound(const Patch& before, const Patch& after) {
  if (before.control_points.rows() != after.control_points.rows() || before.rational() != after.rational())
    throw internal_error("change_bound: the patches are not in one basis");
  const Eigen::MatrixXd d = before.control_points - after.control_points;
  double bound = 0;
  if (!before.rational()) {
    bound = d.rows() ? d.rowwise().norm().maxCoeff() : 0.0;
  } else if (after.weights.minCoeff() <= 0) {
    bound = std::numeric_limits<double>::infinity();
  } else {
    const Eigen::RowVector3d centre =
        0.5 * (before.control_points.colwise().minCoeff() + before.control_points.colwise().maxCoeff());
    const Eigen::MatrixXd x0 = before.control_points.rowwise() - centre;
    const Eigen::MatrixXd x1 = after.control_points.rowwise() - centre;
    const Eigen::MatrixXd dA = x0.array().colwise() * before.weights.array() - x1.array().colwise() * after.weights.array();
    const double dW = (before.weights - after.weights).cwiseAbs().maxCoeff();
    bound = (dA.rowwise().norm().maxCoeff() + x1.rowwise().norm().maxCoeff() * dW) / before.weights.minCoeff();
  }
  return std::isfinite(bound) && after.control_points.allFinite() ? bound : std::numeric_limits<double>::infinity();
}

namespace {

// One removal of u from direction dir of a patch; returns the bound, fills *out.
double try_remove(const Patch& patch, int dir, double u, Patch* out) {
  const auto& U = patch.knots[dir];
  const int p = patch.degrees[dir];
  const int r = static_cast<int>(std::upper_bound(U.begin(), U.end(), u) - U.begin()) - 1;
  if (r < 0 || U[r] != u || r <= p || r >= basis_count(U, p))
    throw bad_input("remove_knot: " + std::to_string(u) + " is not an interior knot of direction " +
                    std::to_string(dir));
  std::vector<double> Un;
  Eigen::MatrixXd P, Qa;
  remove_once(U, p, patch_rows(patch, dir), r, &Un, &P, &Qa);
  *out = patch;
  out->knots[dir] = Un;
  set_patch_rows(out, dir, P, static_cast<int>(P.rows()));
  out->displacement.resize(0, 0);
  Patch again = patch;
  set_patch_rows(&again, dir, Qa, static_cast<int>(Qa.rows()));
  return change_bound(patch, again);
}

}  // namespace

int remove_knot(Patch* patch, int dir, double u, int times, double tol, double* error) {
  if (dir < 0 || dir > 2) throw bad_input("remove_knot: direction must be 0, 1 or 2");
  double acc = 0;
  int removed = 0;
  for (; removed < times; ++removed) {
    if (knot_multiplicity(patch->knots[dir], u) == 0) break;
    Patch cand;
    const double e = try_remove(*patch, dir, u, &cand);
    if (acc + e > tol) break;
    acc += e;
    *patch = std::move(cand);
  }
  if (error) *error = acc;
  return removed;
}

ReductionReport reduce_knots(Patch* patch, double tol, std::array<bool, 3> directions) {
  ReductionReport rep;
  for (;;) {
    // Candidates of this pass, cheapest first; each is re-measured when removed
    // because earlier removals change its neighbourhood.
    struct Cand {
      double err;
      int dir;
      double u;
    };
    std::vector<Cand> cands;
    for (int d = 0; d < 3; ++d) {
      if (!directions[d]) continue;
      const auto br = unique_knots(patch->knots[d]);
      for (size_t k = 1; k + 1 < br.size(); ++k) {
        Patch tmp;
        const double e = try_remove(*patch, d, br[k], &tmp);
        if (rep.error_bound + e <= tol) cands.push_back({e, d, br[k]});
      }
    }
    if (cands.empty()) break;
    std::stable_sort(cands.begin(), cands.end(), [](const Cand& a, const Cand& b) { return a.err < b.err; });
    int removed_this_pass = 0;
    for (const Cand& c : cands) {
      if (knot_multiplicity(patch->knots[c.dir], c.u) == 0) continue;
      Patch tmp;
      const double e = try_remove(*patch, c.dir, c.u, &tmp);
      if (rep.error_bound + e > tol) continue;
      rep.error_bound += e;
      *patch = std::move(tmp);
      ++rep.removed;
      ++rep.removed_per_dir[c.dir];
      ++removed_this_pass;
    }
    if (removed_this_pass == 0) break;
  }
  return rep;
}

}  // namespace igaprep::spline
