#include "igaprep/spline/optimize_jacobian.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "igaprep/core/error.h"
#include "igaprep/spline/basis.h"
#include "igaprep/spline/curve_surface.h"
#include "igaprep/spline/evaluate.h"
#include "igaprep/spline/knot_vector.h"
#include "igaprep/spline/multipatch_topology.h"
#include "igaprep/spline/scaled_jacobian.h"
#include "joint_repair.h"
#include "repair_common.h"

namespace igaprep::spline {

namespace {

using detail::Copy;
using detail::kFixed;
using detail::repair_scaled;
using detail::SampleGrid;

// One basis function's value and derivative at a sample point of one direction.
struct Entry {
  int point;
  double N, dN;
};

// A patch's sample points (a tensor grid, `points` per element and direction)
// with their Jacobians, and per direction and control index the sample
// points in that function's support.
struct PatchSamples {
  std::array<int, 3> n{};                           // sample points per direction
  std::array<std::vector<std::vector<Entry>>, 3> support;  // [direction][control index]
  std::array<std::vector<int>, 3> first;            // [direction][point]: first control index non-zero there
  std::array<int, 3> degree{};
  std::vector<Eigen::Matrix3d> J;                   // per sample point, i fastest
  std::vector<double> q;                            // repair_scaled(J), kept up to date

  int index(int i, int j, int k) const { return i + n[0] * (j + n[1] * k); }
};

// Scaled Jacobians of a patch on a tensor grid (evaluate_grid: sum
// factorisation), i fastest.
std::vector<Eigen::Matrix3d> grid_jacobians(const Patch& p, const std::array<std::vector<double>, 3>& params) {
  const GridEvaluation ev = evaluate_grid(p, params, 1);
  std::vector<Eigen::Matrix3d> J(static_cast<std::size_t>(ev.jacobians.rows()));
  for (Eigen::Index at = 0; at < ev.jacobians.rows(); ++at) J[static_cast<std::size_t>(at)] = grid_jacobian(ev, at);
  return J;
}

PatchSamples sample_patch(const Patch& p, const SampleGrid& params) {
  PatchSamples s;
  for (int d = 0; d < 3; ++d) {
    const int deg = p.degrees[static_cast<std::size_t>(d)];
    const BasisTable tab = basis_table(p.knots[static_cast<std::size_t>(d)], deg, params[static_cast<std::size_t>(d)], 1);
    s.n[static_cast<std::size_t>(d)] = tab.size();
    s.degree[static_cast<std::size_t>(d)] = deg;
    for (int i = 0; i < tab.size(); ++i) s.first[static_cast<std::size_t>(d)].push_back(tab.span[static_cast<std::size_t>(i)] - deg);
    auto& sup = s.support[static_cast<std::size_t>(d)];
    sup.assign(static_cast<std::size_t>(p.count(d)), {});
    for (int i = 0; i < tab.size(); ++i)
      for (int r = 0; r <= deg; ++r) {
        const int a = tab.span[static_cast<std::size_t>(i)] - deg + r;
        sup[static_cast<std::size_t>(a)].push_back({i, tab.at(i, 0)[r], tab.at(i, 1)[r]});
      }
  }
  s.J = grid_jacobians(p, params);
  s.q.resize(s.J.size());
  for (std::size_t i = 0; i < s.J.size(); ++i) s.q[i] = repair_scaled(s.J[i]);
  return s;
}

// The lowest scaled Jacobian of a patch on a sample grid.
double patch_min_at(const Patch& p, const SampleGrid& params) {
  double lo = std::numeric_limits<double>::infinity();
  for (const Eigen::Matrix3d& J : grid_jacobians(p, params)) lo = std::min(lo, repair_scaled(J));
  return lo;
}

class Optimizer {
 public:
  // grids[patch]: that patch's sample grid.
  Optimizer(MultiPatch& mp, const std::vector<SampleGrid>& grids) : mp_(mp) {
    for (std::size_t pi = 0; pi < mp.patches.size(); ++pi) samples_.push_back(sample_patch(mp.patches[pi], grids[pi]));
  }

  // Calls f(J at the point after moving by delta) for every sample point in
  // the support of the copies.
  template <class F>
  void for_support(const std::vector<Copy>& copies, const Eigen::Vector3d& delta, F&& f) {
    for (const Copy& cp : copies) {
      PatchSamples& s = samples_[static_cast<std::size_t>(cp.patch)];
      for (const Entry& ec : s.support[2][static_cast<std::size_t>(cp.c)])
        for (const Entry& eb : s.support[1][static_cast<std::size_t>(cp.b)])
          for (const Entry& ea : s.support[0][static_cast<std::size_t>(cp.a)]) {
            const Eigen::RowVector3d g(ea.dN * eb.N * ec.N, ea.N * eb.dN * ec.N, ea.N * eb.N * ec.dN);
            const std::size_t at = static_cast<std::size_t>(s.index(ea.point, eb.point, ec.point));
            f(s.J[at], delta * g, s.q[at]);
          }
    }
  }

  // Lowest and soft minimum of the scaled Jacobians in the copies' support
  // after a move by delta.
  void measure(const std::vector<Copy>& copies, const Eigen::Vector3d& delta, double* worst, double* soft) {
    thread_local std::vector<double> q;
    q.clear();
    double lo = std::numeric_limits<double>::infinity();
    for_support(copies, delta, [&](const Eigen::Matrix3d& J, const Eigen::Matrix3d& dJ, double) {
      const double v = repair_scaled(J + dJ);
      if (std::isfinite(v)) {
        q.push_back(v);
        lo = std::min(lo, v);
      }
    });
    *worst = lo;
    if (!soft) return;
    constexpr double beta = 40.0;
    double sum = 0.0;
    for (double v : q) sum += std::exp(-beta * (v - lo));
    *soft = q.empty() ? lo : lo - std::log(sum) / beta;
  }

  // The sample points in the copies' support whose scaled Jacobian is below
  // `relevance` (the others are checked once more before a move is kept).
  struct Item {
    const Eigen::Matrix3d* J;
    Eigen::RowVector3d g;
  };
  void gather(const std::vector<Copy>& copies, double relevance, std::vector<Item>* items) {
    items->clear();
    for (const Copy& cp : copies) {
      PatchSamples& s = samples_[static_cast<std::size_t>(cp.patch)];
      for (const Entry& ec : s.support[2][static_cast<std::size_t>(cp.c)])
        for (const Entry& eb : s.support[1][static_cast<std::size_t>(cp.b)])
          for (const Entry& ea : s.support[0][static_cast<std::size_t>(cp.a)]) {
            const std::size_t at = static_cast<std::size_t>(s.index(ea.point, eb.point, ec.point));
            if (s.q[at] < relevance)
              items->push_back({&s.J[at], Eigen::RowVector3d(ea.dN * eb.N * ec.N, ea.N * eb.dN * ec.N, ea.N * eb.N * ec.dN)});
          }
    }
  }
  static void measure(const std::vector<Item>& items, const Eigen::Vector3d& delta, double* worst, double* soft) {
    double lo = std::numeric_limits<double>::infinity();
    thread_local std::vector<double> q;
    q.clear();
    for (const Item& it : items) {
      const double v = repair_scaled(*it.J + delta * it.g);
      if (std::isfinite(v)) {
        q.push_back(v);
        lo = std::min(lo, v);
      }
    }
    *worst = lo;
    if (!soft) return;
    constexpr double beta = 40.0;
    double sum = 0.0;
    for (double v : q) sum += std::exp(-beta * (v - lo));
    *soft = q.empty() ? lo : lo - std::log(sum) / beta;
  }

  void apply(const std::vector<Copy>& copies, const Eigen::Vector3d& delta) {
    for_support(copies, delta, [](Eigen::Matrix3d& J, const Eigen::Matrix3d& dJ, double& q) {
      J += dJ;
      q = repair_scaled(J);
    });
    for (const Copy& cp : copies) mp_.patches[static_cast<std::size_t>(cp.patch)].control_points.row(cp.local) += delta.transpose();
  }

  // Calls f(patch, local control point) for every control point whose
  // support holds a sample point below the target.
  template <class F>
  void below_target(double target, F&& f) const {
    for (std::size_t pi = 0; pi < samples_.size(); ++pi) {
      const PatchSamples& s = samples_[pi];
      const Patch& p = mp_.patches[pi];
      for (int k = 0; k < s.n[2]; ++k)
        for (int j = 0; j < s.n[1]; ++j)
          for (int i = 0; i < s.n[0]; ++i) {
            if (!(s.q[static_cast<std::size_t>(s.index(i, j, k))] < target)) continue;
            const int a0 = s.first[0][static_cast<std::size_t>(i)], b0 = s.first[1][static_cast<std::size_t>(j)],
                      c0 = s.first[2][static_cast<std::size_t>(k)];
            for (int c = c0; c <= c0 + s.degree[2]; ++c)
              for (int b = b0; b <= b0 + s.degree[1]; ++b)
                for (int a = a0; a <= a0 + s.degree[0]; ++a) f(static_cast<int>(pi), p.index(a, b, c));
          }
    }
  }

  // One Gauss-Seidel step for the control point held by `copies` (on
  // surface `con`, or free: -1): along the gradient of the soft minimum of
  // the scaled Jacobians in its support, the longest of a halving sequence of
  // steps that raises their minimum. Returns whether it moved.
  bool improve(const std::vector<Copy>& copies, int con, const SlideFn& slide, double target) {
    // The step is chosen on the points below target + 0.2 only (target +
    // 0.4 took twice as long for the same result on ring2 and torus3); a
    // step is kept only after all points of the support were checked.
    gather(copies, std::min(1.0, target + 0.2), &items_);
    double worst, soft;
    measure(items_, Eigen::Vector3d::Zero(), &worst, &soft);
    if (!(worst < target)) return false;
    const Eigen::Vector3d x =
        mp_.patches[static_cast<std::size_t>(copies.front().patch)].control_points.row(copies.front().local).transpose();
    const double edge = detail::nearest_neighbour(mp_, copies, x);
    if (!std::isfinite(edge)) return false;
    // Central differences of the soft minimum.
    const double h = 1e-5 * edge;
    Eigen::Vector3d grad;
    for (int d = 0; d < 3; ++d) {
      const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(d);
      double w1, s1, w2, s2;
      measure(items_, e, &w1, &s1);
      measure(items_, -e, &w2, &s2);
      grad[d] = (s1 - s2) / (2.0 * h);
    }
    if (!(grad.norm() > 0.0)) return false;
    grad.normalize();
    for (double a = 0.25; a > 0.002; a *= 0.5) {
      Eigen::Vector3d y = x + a * edge * grad;
      if (con >= 0) y = slide(con, x, y);
      const Eigen::Vector3d delta = y - x;
      double w1, all;
      measure(items_, delta, &w1, nullptr);
      if (!(w1 > worst + 1e-9)) continue;
      measure(copies, delta, &all, nullptr);
      if (all > worst + 1e-9) {
        apply(copies, delta);
        return true;
      }
    }
    return false;
  }

  void global(double target, double* worst, int* below) const {
    *worst = std::numeric_limits<double>::infinity();
    *below = 0;
    for (const PatchSamples& s : samples_)
      for (const double v : s.q) {
        if (!std::isfinite(v)) continue;
        *worst = std::min(*worst, v);
        if (v < target) ++*below;
      }
    if (!std::isfinite(*worst)) *worst = 1.0;
  }

 private:
  MultiPatch& mp_;
  std::vector<PatchSamples> samples_;
  std::vector<Item> items_;
};

// Sweeps without a new low in the number of active control points before
// the repair stops (docs/decomposition.md, the fit).
constexpr int kStallSweeps = 10;

void check_options(const MultiPatch& mp, const JacobianOptimizationOptions& options) {
  if (options.sweeps < 0 || options.iterations < 0 || options.points < 2 || !(options.target >= 0.0 && options.target <= 1.0))
    throw bad_input("optimize_jacobians: need sweeps >= 0, iterations >= 0, points >= 2 and a target in [0, 1]");
  for (const Patch& p : mp.patches)
    if (p.rational()) throw bad_input("optimize_jacobians: rational patches are not supported");
}

// One repair of a model: its passes share the control points' numbering,
// copies and constraints, and the record of which moved.
class Repair {
 public:
  Repair(MultiPatch& mp, const SlideFn& slide, const std::vector<std::pair<int, Side>>& fixed_sides,
         const JacobianOptimizationOptions& options)
      : mp_(mp),
        slide_(slide),
        options_(options),
        num_(global_numbering(mp)),
        copies_(detail::control_point_copies(mp, num_)),
        cons_(detail::control_point_constraints(mp, num_, fixed_sides, static_cast<bool>(slide))),
        moved_(static_cast<std::size_t>(num_.count), 0) {
    for (int g = 0; g < num_.count; ++g) start_.push_back(position(g));
  }

  // Every patch's grid of `points` per element and direction.
  std::vector<SampleGrid> grids(int points) const {
    std::vector<SampleGrid> out;
    for (const Patch& p : mp_.patches) out.push_back(detail::repair_sample_grid(p, points));
    return out;
  }

  void measure_before(const std::vector<SampleGrid>& grids) {
    Optimizer(mp_, grids).global(options_.target, &out_.min_before, &out_.below_before);
  }

  // The joint optimization first, then sweeps for what it left below the target.
  void run(const std::vector<SampleGrid>& grids, double target) {
    if (options_.iterations > 0) {
      const detail::JointRepairResult j = detail::joint_repair(mp_, num_, copies_, cons_, slide_, target, grids,
                                                               options_.iterations, &moved_, options_.progress);
      out_.joint_variables += j.variables;
      out_.joint_iterations += j.iterations;
      out_.joint_stop = j.stop;
    }
    Optimizer opt(mp_, grids);
    sweeps(opt, target);
    opt.global(options_.target, &out_.min_after, &out_.below_after);
  }

  // A fold can open between the sample points where control points moved:
  // those patches are sampled twice as densely, and where that finds a point
  // well below the target they are repaired again on the dense samples.
  void dense_pass(std::vector<SampleGrid>& grids) {
    std::vector<char> touched(mp_.patches.size(), 0);
    for (int g = 0; g < num_.count; ++g)
      if (moved_[static_cast<std::size_t>(g)])
        for (const Copy& c : copies_[static_cast<std::size_t>(g)]) touched[static_cast<std::size_t>(c.patch)] = 1;
    bool any = false;
    for (std::size_t pi = 0; pi < mp_.patches.size(); ++pi) {
      if (!touched[pi]) continue;
      SampleGrid dense = detail::repair_sample_grid(mp_.patches[pi], dense_points());
      if (!(patch_min_at(mp_.patches[pi], dense) < options_.target - 0.1)) continue;
      grids[pi] = std::move(dense);
      any = true;
      ++out_.dense_patches;
    }
    if (any) run(grids, options_.target);
  }

  // Each patch's dense grid with the witnesses in it added, each with the
  // points halfway to its neighbouring dense samples: the fold around a
  // witness, not only its one point, weighs in the repair.
  std::vector<SampleGrid> focus_grids(const std::vector<std::pair<int, Eigen::Vector3d>>& witnesses) const {
    std::vector<std::vector<Eigen::Vector3d>> at(mp_.patches.size());
    for (const auto& [patch, t] : witnesses) {
      if (patch < 0 || patch >= static_cast<int>(mp_.patches.size()))
        throw bad_input("optimize_jacobians: a witness names patch " + std::to_string(patch) + " of " +
                        std::to_string(mp_.patches.size()));
      const Eigen::Vector3d half = half_dense_spacing(mp_.patches[static_cast<std::size_t>(patch)], t);
      for (const double s : {-1.0, 0.0, 1.0}) at[static_cast<std::size_t>(patch)].push_back(t + s * half);
    }
    std::vector<SampleGrid> out;
    for (std::size_t pi = 0; pi < mp_.patches.size(); ++pi)
      out.push_back(detail::repair_sample_grid(mp_.patches[pi], dense_points(), at[pi]));
    return out;
  }

  // Samples still negative on a patch's focus grid get a last pass aimed at
  // them alone: with the target at 0 the many samples between 0 and the
  // target no longer weigh against the moves that would open the folds. It
  // is kept only if it raises their lowest sample. The other patches keep
  // their grids, which are within their focus grids, all non-negative there:
  // the lowest sample after the pass is the repair's own min_after.
  void aim_at_negative_samples(std::vector<SampleGrid> grids, const std::vector<SampleGrid>& focus) {
    double lowest_before = 0.0;
    for (std::size_t pi = 0; pi < mp_.patches.size(); ++pi) {
      const double lowest = patch_min_at(mp_.patches[pi], focus[pi]);
      if (!(lowest < 0.0)) continue;
      grids[pi] = focus[pi];
      ++out_.focus_patches;
      lowest_before = std::min(lowest_before, lowest);
    }
    if (out_.focus_patches == 0) return;
    const JacobianOptimizationResult before = out_;
    const std::vector<char> moved_before = moved_;
    std::vector<Eigen::MatrixXd> kept;
    for (const Patch& p : mp_.patches) kept.push_back(p.control_points);
    run(grids, 0.0);
    out_.focus_min_before = lowest_before;
    out_.focus_min_after = out_.min_after;
    if (out_.focus_min_after > out_.focus_min_before) return;
    for (std::size_t pi = 0; pi < mp_.patches.size(); ++pi) mp_.patches[pi].control_points = kept[pi];
    out_ = before;
    moved_ = moved_before;
    out_.focus_kept = false;
    out_.focus_min_before = out_.focus_min_after = lowest_before;
  }

  JacobianOptimizationResult& result() { return out_; }

  // The result with the moved control points counted and measured.
  JacobianOptimizationResult finish() {
    for (int g = 0; g < num_.count; ++g) {
      if (!moved_[static_cast<std::size_t>(g)]) continue;
      ++out_.moved_points;
      out_.max_move = std::max(out_.max_move, (position(g) - start_[static_cast<std::size_t>(g)]).norm());
    }
    return out_;
  }

 private:
  int dense_points() const { return 2 * options_.points - 1; }

  // Per direction, half the dense samples' spacing in the element holding t.
  Eigen::Vector3d half_dense_spacing(const Patch& p, const Eigen::Vector3d& t) const {
    Eigen::Vector3d half;
    for (int d = 0; d < 3; ++d) {
      const std::vector<double> brk = unique_knots(p.knots[static_cast<std::size_t>(d)]);
      auto hi = std::upper_bound(brk.begin(), brk.end(), t[d]);
      if (hi == brk.end()) --hi;
      if (hi == brk.begin()) ++hi;
      half[d] = (*hi - *(hi - 1)) / (2.0 * (dense_points() - 1));
    }
    return half;
  }

  Eigen::Vector3d position(int g) const {
    const Copy& c0 = copies_[static_cast<std::size_t>(g)].front();
    return mp_.patches[static_cast<std::size_t>(c0.patch)].control_points.row(c0.local).transpose();
  }

  // Sweeps until no control point moves, or the number of control points
  // next to samples below the target has not fallen to a new low for
  // kStallSweeps sweeps (the folds left are held by points that cannot
  // move them, and further moves only cost fidelity), or options.sweeps.
  void sweeps(Optimizer& opt, double target) {
    long long fewest_active = std::numeric_limits<long long>::max();
    int since_fewest = 0;
    out_.stop_reason = "the sweep limit";
    for (int sweep = 0; sweep < options_.sweeps; ++sweep) {
      if (options_.progress)
        options_.progress("Jacobian repair (sweeps)", static_cast<std::size_t>(sweep), static_cast<std::size_t>(options_.sweeps));
      std::vector<char> active(static_cast<std::size_t>(num_.count), 0);
      opt.below_target(target, [&](int patch, int local) {
        active[static_cast<std::size_t>(num_.global[static_cast<std::size_t>(patch)][static_cast<std::size_t>(local)])] = 1;
      });
      const long long n_active = std::count(active.begin(), active.end(), 1);
      if (n_active == 0) {
        out_.stop_reason = "the target reached";
        break;
      }
      if (n_active < fewest_active) {
        fewest_active = n_active;
        since_fewest = 0;
      } else if (++since_fewest >= kStallSweeps) {
        out_.stop_reason = "no progress in " + std::to_string(kStallSweeps) + " sweeps";
        break;
      }
      long long moves = 0;
      for (int g = 0; g < num_.count; ++g) {
        const int con = cons_[static_cast<std::size_t>(g)];
        if (con == kFixed || !active[static_cast<std::size_t>(g)]) continue;
        if (opt.improve(copies_[static_cast<std::size_t>(g)], con, slide_, target)) {
          moved_[static_cast<std::size_t>(g)] = 1;
          ++moves;
        }
      }
      out_.moves += moves;
      ++out_.sweeps;
      if (moves == 0) {
        out_.stop_reason = "no control point can move";
        break;
      }
    }
  }

  MultiPatch& mp_;
  const SlideFn& slide_;
  const JacobianOptimizationOptions& options_;
  GlobalNumbering num_;
  std::vector<std::vector<Copy>> copies_;
  std::vector<int> cons_;
  std::vector<char> moved_;
  std::vector<Eigen::Vector3d> start_;
  JacobianOptimizationResult out_;
};

}  // namespace

JacobianOptimizationResult optimize_jacobians(MultiPatch& mp, const SlideFn& slide,
                                              const std::vector<std::pair<int, Side>>& fixed_sides,
                                              const JacobianOptimizationOptions& options) {
  check_options(mp, options);
  Repair repair(mp, slide, fixed_sides, options);
  std::vector<SampleGrid> grids = repair.grids(options.points);
  repair.measure_before(grids);
  repair.run(grids, options.target);
  repair.dense_pass(grids);
  if (repair.result().min_after < 0.0) repair.aim_at_negative_samples(grids, repair.focus_grids({}));
  return repair.finish();
}

JacobianOptimizationResult repair_at_witnesses(MultiPatch& mp, const SlideFn& slide,
                                               const std::vector<std::pair<int, Side>>& fixed_sides,
                                               const std::vector<std::pair<int, Eigen::Vector3d>>& witnesses,
                                               const JacobianOptimizationOptions& options) {
  check_options(mp, options);
  Repair repair(mp, slide, fixed_sides, options);
  const std::vector<SampleGrid> grids = repair.grids(options.points);
  repair.measure_before(grids);
  repair.aim_at_negative_samples(grids, repair.focus_grids(witnesses));
  JacobianOptimizationResult& r = repair.result();
  if (r.focus_patches > 0) {
    r.min_before = std::min(r.min_before, r.focus_min_before);
    r.min_after = r.focus_min_after;
  } else {
    r.min_after = r.min_before;
  }
  return repair.finish();
}

}  // namespace igaprep::spline
