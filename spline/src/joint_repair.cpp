#include "joint_repair.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>

#include <Eigen/SVD>
#include <ceres/ceres.h>
#include <glog/logging.h>

#include "igaprep/core/parallel.h"
#include "igaprep/spline/evaluate.h"

namespace igaprep::spline::detail {
namespace {

// Samples up to this far above the target choose the control points that
// move: a point next to a sample just above it may have to give way.
constexpr double kReach = 0.1;
// The penalty pushes the samples this far above the target, so that they
// get there in a finite number of steps (the penalty's pull fades at its aim).
constexpr double kMargin = 0.05;
// Weight of kStay |y|^2 per control point, y its move in units of the
// distance to its nearest neighbour: without it a point can leave the model
// (a fold is undone as well by a huge element).
constexpr double kStay = 0.01;
// The same for a point on T1 or a Ti, where a move also costs fidelity
// (torus3: 0.01 gave fidelity 0.177 %, 0.1 0.159 %, 1.0 0.163 %).
constexpr double kStaySurface = 0.1;

// A control point that moves: x = x0 + h T bounded_move(y) for a free one
// (T = I); for one on a surface, T spans the surface's tangent plane at x0
// and the point is put back on the surface by `slide` at the end.
struct Variable {
  int global = 0, surface = kFree;
  Eigen::Vector3d x0, on_surface;  // start; slide(x0, x0), so that y = 0 is x0 exactly
  double h = 1.0;                  // distance to the nearest neighbour: the unit of y
  Eigen::MatrixXd T;               // 3 x dof
  int offset = 0;                  // first of its dof in y
};

// A patch holding moving control points, evaluated on the samples those can reach.
struct PatchWork {
  Patch work;
  GridBasis basis;
  std::vector<std::pair<int, int>> rows;  // (local control point, variable)
  std::vector<int> variable_of;           // per local control point, -1 if it stays
};

// A control point's move, in units of its neighbour distance, for the
// unknowns y: y / sqrt(1 + |y|^2), shorter than one neighbour distance
// whatever y is. Unbounded, points left the propeller by tens of mm where
// the sum over thousands of folded samples outweighed the stay term (at
// most 3 distances: 20 mm, volume +8 %; at most 1: -0.4 %).
Eigen::VectorXd bounded_move(const Eigen::Ref<const Eigen::VectorXd>& y) { return y / std::sqrt(1.0 + y.squaredNorm()); }

// d bounded_move / d y.
Eigen::MatrixXd bounded_move_jacobian(const Eigen::Ref<const Eigen::VectorXd>& y) {
  const double r = 1.0 + y.squaredNorm();
  return (r * Eigen::MatrixXd::Identity(y.size(), y.size()) - y * y.transpose()) / (r * std::sqrt(r));
}

// d q / d J for q = det J / (|J0| |J1| |J2|), the scaled Jacobian.
Eigen::Matrix3d scaled_jacobian_gradient(const Eigen::Matrix3d& J, double q) {
  Eigen::Matrix3d cof;
  cof.col(0) = J.col(1).cross(J.col(2));
  cof.col(1) = J.col(2).cross(J.col(0));
  cof.col(2) = J.col(0).cross(J.col(1));
  const Eigen::Vector3d n2(J.col(0).squaredNorm(), J.col(1).squaredNorm(), J.col(2).squaredNorm());
  const double prod = std::sqrt(n2[0] * n2[1] * n2[2]);
  Eigen::Matrix3d G;
  for (int d = 0; d < 3; ++d) G.col(d) = cof.col(d) / prod - q * J.col(d) / n2[d];
  return G;
}

// The tangent directions of a surface at x (1 or 2 columns; none at a
// point `slide` does not move), read off how `slide` moves small steps.
Eigen::MatrixXd tangent_basis(const SlideFn& slide, int surface, const Eigen::Vector3d& x, double h) {
  const double eps = 1e-3 * h;
  const Eigen::Vector3d base = slide(surface, x, x);
  Eigen::Matrix3d A;
  for (int d = 0; d < 3; ++d) A.col(d) = (slide(surface, x, x + eps * Eigen::Vector3d::Unit(d)) - base) / eps;
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(A, Eigen::ComputeFullU);
  int dof = 0;
  while (dof < 2 && svd.singularValues()[dof] > 0.5) ++dof;
  return svd.matrixU().leftCols(dof);
}

class Penalty : public ceres::FirstOrderFunction {
 public:
  Penalty(std::vector<Variable> vars, std::vector<PatchWork> work, const SlideFn& slide, double target, int dof)
      : vars_(std::move(vars)), work_(std::move(work)), slide_(slide), target_(target), aim_(target + kMargin), dof_(dof) {}

  int NumParameters() const override { return dof_; }

  // Where a variable is during the optimization: sliding points move in
  // their tangent plane, which keeps E smooth (a closest-point projection
  // inside E broke the line search on ring2).
  Eigen::Vector3d position(const Variable& v, const double* y) const {
    return v.x0 + v.h * v.T * bounded_move(Eigen::Map<const Eigen::VectorXd>(y + v.offset, v.T.cols()));
  }
  static double stay(const Variable& v) { return v.surface == kFree ? kStay : kStaySurface; }

  // Where it goes at the end: a sliding point put back on its surface.
  Eigen::Vector3d final_position(const Variable& v, const double* y) const {
    const Eigen::Vector3d x = position(v, y);
    return v.surface == kFree ? x : Eigen::Vector3d(v.x0 + slide_(v.surface, v.x0, x) - v.on_surface);
  }

  bool Evaluate(const double* y, double* cost, double* gradient) const override {
    last_y_.clear();
    std::vector<Eigen::Vector3d> X(vars_.size());
    for (std::size_t v = 0; v < vars_.size(); ++v) X[v] = position(vars_[v], y);
    std::vector<Eigen::Vector3d> gx(gradient ? vars_.size() : 0, Eigen::Vector3d::Zero());
    double sum = samples_penalty(X, gradient ? &gx : nullptr);
    for (const Variable& v : vars_) sum += stay(v) * Eigen::Map<const Eigen::VectorXd>(y + v.offset, v.T.cols()).squaredNorm();
    if (!std::isfinite(sum)) return false;
    last_y_.assign(y, y + dof_);
    *cost = sum;
    if (gradient)
      for (std::size_t v = 0; v < vars_.size(); ++v) {
        const Variable& var = vars_[v];
        const Eigen::Map<const Eigen::VectorXd> yv(y + var.offset, var.T.cols());
        Eigen::Map<Eigen::VectorXd>(gradient + var.offset, var.T.cols()) =
            bounded_move_jacobian(yv).transpose() * (var.h * var.T.transpose() * gx[v]) + 2.0 * stay(var) * yv;
      }
    return true;
  }

  const std::vector<Variable>& variables() const { return vars_; }

  // The number of samples below the target at y, if the last evaluation was there (-1 otherwise).
  long below_at(const double* y) const {
    const bool there = last_y_.size() == static_cast<std::size_t>(dof_) && std::equal(last_y_.begin(), last_y_.end(), y);
    return there ? last_below_ : -1;
  }

 private:
  // The samples' share of E at positions X and (if gx) its gradient in X;
  // counts the samples below the target. The patches are dealt into a fixed
  // number of shares (parallel_for runs them on the cores), each with its own
  // gradient, summed in share order: the result does not depend on the cores.
  // Two shares, as on the 2-core machine the documented figures come from.
  double samples_penalty(const std::vector<Eigen::Vector3d>& X, std::vector<Eigen::Vector3d>* gx) const {
    constexpr std::size_t kShares = 2;
    const std::size_t parts = std::max<std::size_t>(1, std::min(kShares, work_.size()));
    std::vector<double> sums(parts, 0.0);
    std::vector<long> below(parts, 0);
    std::vector<std::vector<Eigen::Vector3d>> gxs(parts, std::vector<Eigen::Vector3d>(gx ? gx->size() : 0, Eigen::Vector3d::Zero()));
    auto share = [&](std::size_t t) {
      for (std::size_t w = t; w < work_.size(); w += parts) sums[t] += patch_penalty(work_[w], X, gx ? &gxs[t] : nullptr, &below[t]);
    };
    parallel_for(parts, share);
    for (std::size_t t = 0; gx && t < parts; ++t)
      for (std::size_t v = 0; v < gx->size(); ++v) (*gx)[v] += gxs[t][v];
    last_below_ = std::accumulate(below.begin(), below.end(), 0L);
    return std::accumulate(sums.begin(), sums.end(), 0.0);
  }

  // The patch's share of E at positions X, and (if gx) its gradient in X.
  double patch_penalty(PatchWork& pw, const std::vector<Eigen::Vector3d>& X, std::vector<Eigen::Vector3d>* gx,
                       long* below) const {
    Patch& p = pw.work;
    for (const auto& [local, v] : pw.rows) p.control_points.row(local) = X[static_cast<std::size_t>(v)].transpose();
    const GridEvaluation ev = evaluate_grid(p, pw.basis);
    const int mu = pw.basis.size(0), mv = pw.basis.size(1);
    double sum = 0.0;
    for (Eigen::Index at = 0; at < ev.jacobians.rows(); ++at) {
      const Eigen::Matrix3d J = grid_jacobian(ev, at);
      const double q = repair_scaled(J);
      if (q < target_) ++*below;
      if (!(q < aim_)) continue;  // also a degenerate J: no move raises it
      const double gap = aim_ - q;
      sum += gap * gap;
      if (!gx) continue;
      const int i = static_cast<int>(at % mu), j = static_cast<int>((at / mu) % mv), k = static_cast<int>(at / (mu * mv));
      scatter(pw, {i, j, k}, -2.0 * gap * scaled_jacobian_gradient(J, q), gx);
    }
    return sum;
  }

  // Adds dE/dJ at grid point ijk to the gradients of the variables in its support.
  static void scatter(const PatchWork& pw, const std::array<int, 3>& ijk, const Eigen::Matrix3d& G,
                      std::vector<Eigen::Vector3d>* gx) {
    const Patch& p = pw.work;
    std::array<const double*, 3> N, dN;
    std::array<int, 3> first;
    for (int d = 0; d < 3; ++d) {
      const BasisTable& t = pw.basis.tables[static_cast<std::size_t>(d)];
      const int at = ijk[static_cast<std::size_t>(d)];
      N[static_cast<std::size_t>(d)] = t.at(at, 0);
      dN[static_cast<std::size_t>(d)] = t.at(at, 1);
      first[static_cast<std::size_t>(d)] = t.span[static_cast<std::size_t>(at)] - p.degrees[static_cast<std::size_t>(d)];
    }
    for (int c = 0; c <= p.degrees[2]; ++c)
      for (int b = 0; b <= p.degrees[1]; ++b)
        for (int a = 0; a <= p.degrees[0]; ++a) {
          const int v = pw.variable_of[static_cast<std::size_t>(p.index(first[0] + a, first[1] + b, first[2] + c))];
          if (v < 0) continue;
          const Eigen::Vector3d g(dN[0][a] * N[1][b] * N[2][c], N[0][a] * dN[1][b] * N[2][c], N[0][a] * N[1][b] * dN[2][c]);
          (*gx)[static_cast<std::size_t>(v)] += G * g;
        }
  }

  std::vector<Variable> vars_;
  mutable std::vector<PatchWork> work_;  // scratch copies of the patches, one evaluation at a time
  const SlideFn& slide_;
  double target_, aim_;  // the samples are pushed towards aim_; the optimization stops once all reach target_
  mutable std::vector<double> last_y_;
  mutable long last_below_ = -1;
  int dof_;
};

// Global control points next to a sample below `below` that may move.
std::vector<char> movable_near_low_samples(const MultiPatch& mp, const GlobalNumbering& num, const std::vector<int>& cons,
                                           const std::vector<SampleGrid>& grids, double below) {
  std::vector<char> out(static_cast<std::size_t>(num.count), 0);
  for (std::size_t pi = 0; pi < mp.patches.size(); ++pi) {
    const Patch& p = mp.patches[pi];
    const GridBasis basis = grid_basis(p, grids[pi], 1);
    const GridEvaluation ev = evaluate_grid(p, basis);
    const int mu = basis.size(0), mv = basis.size(1);
    for (Eigen::Index at = 0; at < ev.jacobians.rows(); ++at) {
      if (!(repair_scaled(grid_jacobian(ev, at)) < below)) continue;
      const std::array<int, 3> ijk{{static_cast<int>(at % mu), static_cast<int>((at / mu) % mv), static_cast<int>(at / (mu * mv))}};
      std::array<int, 3> first;
      for (int d = 0; d < 3; ++d)
        first[static_cast<std::size_t>(d)] = basis.tables[static_cast<std::size_t>(d)].span[static_cast<std::size_t>(ijk[static_cast<std::size_t>(d)])] -
                                             p.degrees[static_cast<std::size_t>(d)];
      for (int c = 0; c <= p.degrees[2]; ++c)
        for (int b = 0; b <= p.degrees[1]; ++b)
          for (int a = 0; a <= p.degrees[0]; ++a) {
            const int g = num.global[pi][static_cast<std::size_t>(p.index(first[0] + a, first[1] + b, first[2] + c))];
            if (cons[static_cast<std::size_t>(g)] != kFixed) out[static_cast<std::size_t>(g)] = 1;
          }
    }
  }
  return out;
}

std::vector<Variable> make_variables(const MultiPatch& mp, const std::vector<std::vector<Copy>>& copies,
                                     const std::vector<int>& cons, const std::vector<char>& movable, const SlideFn& slide) {
  std::vector<Variable> vars;
  int offset = 0;
  for (std::size_t g = 0; g < movable.size(); ++g) {
    if (!movable[g]) continue;
    Variable v;
    v.global = static_cast<int>(g);
    v.surface = cons[g];
    const Copy& c0 = copies[g].front();
    v.x0 = mp.patches[static_cast<std::size_t>(c0.patch)].control_points.row(c0.local).transpose();
    v.h = nearest_neighbour(mp, copies[g], v.x0);
    if (!std::isfinite(v.h)) continue;
    if (v.surface == kFree) {
      v.T = Eigen::Matrix3d::Identity();
    } else {
      v.T = tangent_basis(slide, v.surface, v.x0, v.h);
      v.on_surface = slide(v.surface, v.x0, v.x0);
    }
    if (v.T.cols() == 0) continue;
    v.offset = offset;
    offset += static_cast<int>(v.T.cols());
    vars.push_back(std::move(v));
  }
  return vars;
}

// The patches that hold a variable, each with the samples its variables reach.
std::vector<PatchWork> make_work(const MultiPatch& mp, const std::vector<std::vector<Copy>>& copies,
                                 const std::vector<Variable>& vars, const std::vector<SampleGrid>& grids) {
  std::vector<int> work_of(mp.patches.size(), -1);
  std::vector<PatchWork> work;
  std::vector<std::array<std::array<double, 2>, 3>> range;  // per work: parameter box its variables reach
  for (std::size_t v = 0; v < vars.size(); ++v)
    for (const Copy& c : copies[static_cast<std::size_t>(vars[v].global)]) {
      const Patch& p = mp.patches[static_cast<std::size_t>(c.patch)];
      int& w = work_of[static_cast<std::size_t>(c.patch)];
      if (w < 0) {
        w = static_cast<int>(work.size());
        work.push_back({p, {}, {}, std::vector<int>(static_cast<std::size_t>(p.control_points.rows()), -1)});
        range.push_back({{{{1e300, -1e300}}, {{1e300, -1e300}}, {{1e300, -1e300}}}});
      }
      PatchWork& pw = work[static_cast<std::size_t>(w)];
      pw.rows.emplace_back(c.local, static_cast<int>(v));
      pw.variable_of[static_cast<std::size_t>(c.local)] = static_cast<int>(v);
      const std::array<int, 3> idx{{c.a, c.b, c.c}};
      for (int d = 0; d < 3; ++d) {
        const auto& U = p.knots[static_cast<std::size_t>(d)];
        const int i = idx[static_cast<std::size_t>(d)], deg = p.degrees[static_cast<std::size_t>(d)];
        auto& r = range[static_cast<std::size_t>(w)][static_cast<std::size_t>(d)];
        r[0] = std::min(r[0], U[static_cast<std::size_t>(i)]);
        r[1] = std::max(r[1], U[static_cast<std::size_t>(i + deg + 1)]);
      }
    }
  for (std::size_t pi = 0; pi < mp.patches.size(); ++pi) {
    const int w = work_of[pi];
    if (w < 0) continue;
    SampleGrid params = grids[pi];
    for (int d = 0; d < 3; ++d) {
      const auto& r = range[static_cast<std::size_t>(w)][static_cast<std::size_t>(d)];
      auto& t = params[static_cast<std::size_t>(d)];
      t.erase(std::remove_if(t.begin(), t.end(), [&](double x) { return x < r[0] || x > r[1]; }), t.end());
    }
    work[static_cast<std::size_t>(w)].basis = grid_basis(mp.patches[pi], params, 1);
  }
  return work;
}

// Ceres reports a failed line search through glog on stderr; a library does
// not print (the result says why the optimization stopped).
class QuietCeres {
 public:
  QuietCeres() : saved_(FLAGS_minloglevel) { FLAGS_minloglevel = google::GLOG_ERROR; }
  ~QuietCeres() { FLAGS_minloglevel = saved_; }
  QuietCeres(const QuietCeres&) = delete;
  QuietCeres& operator=(const QuietCeres&) = delete;

 private:
  int saved_;
};

// Stops the optimization once no sample is below the target, or when the
// number below has not reached a new low for kStallIterations iterations
// (the sweeps then finish what is left).
constexpr int kStallIterations = 20;
class StopAtTarget : public ceres::IterationCallback {
 public:
  StopAtTarget(const Penalty& penalty, const double* y, const ProgressCallback& progress, int limit)
      : penalty_(penalty), y_(y), progress_(progress), limit_(limit) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    if (progress_)
      progress_("Jacobian repair (optimization)", static_cast<std::size_t>(std::min(s.iteration, limit_)),
                static_cast<std::size_t>(limit_));
    const long below = penalty_.below_at(y_);
    if (below == 0) return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    if (below > 0 && below < fewest_) {
      fewest_ = below;
      since_fewest_ = 0;
    } else if (++since_fewest_ >= kStallIterations) {
      stalled_ = true;
      return ceres::SOLVER_ABORT;
    }
    return ceres::SOLVER_CONTINUE;
  }
  bool stalled() const { return stalled_; }

 private:
  const Penalty& penalty_;
  const double* y_;
  const ProgressCallback& progress_;
  int limit_;
  long fewest_ = std::numeric_limits<long>::max();
  int since_fewest_ = 0;
  bool stalled_ = false;
};

std::string stop_reason(const ceres::GradientProblemSolver::Summary& s, const StopAtTarget& stop) {
  if (stop.stalled()) return "no progress in " + std::to_string(kStallIterations) + " iterations";
  if (s.termination_type == ceres::USER_SUCCESS) return "the target reached";
  if (s.termination_type == ceres::NO_CONVERGENCE) return "the iteration limit";
  if (s.termination_type == ceres::CONVERGENCE) return "no further descent";
  return "the line search failed";
}

}  // namespace

JointRepairResult joint_repair(MultiPatch& mp, const GlobalNumbering& num, const std::vector<std::vector<Copy>>& copies,
                               const std::vector<int>& cons,
                               const SlideFn& slide, double target, const std::vector<SampleGrid>& grids, int iterations,
                               std::vector<char>* moved, const ProgressCallback& progress) {
  JointRepairResult out;
  std::vector<Variable> vars =
      make_variables(mp, copies, cons, movable_near_low_samples(mp, num, cons, grids, std::min(1.0, target + kReach)), slide);
  if (vars.empty()) {
    out.stop = "no control point can move";
    return out;
  }
  out.variables = static_cast<int>(vars.size());
  const int dof = vars.back().offset + static_cast<int>(vars.back().T.cols());
  std::vector<PatchWork> work = make_work(mp, copies, vars, grids);
  auto* penalty = new Penalty(std::move(vars), std::move(work), slide, target, dof);
  ceres::GradientProblem problem(penalty);  // owns penalty
  std::vector<double> y(static_cast<std::size_t>(dof), 0.0);
  double cost;
  penalty->Evaluate(y.data(), &cost, nullptr);
  if (penalty->below_at(y.data()) == 0) {
    out.stop = "the target reached";
    return out;
  }
  ceres::GradientProblemSolver::Options options;
  options.line_search_direction_type = ceres::LBFGS;
  options.max_num_iterations = iterations;
  options.logging_type = ceres::SILENT;
  options.function_tolerance = 1e-8;
  options.update_state_every_iteration = true;  // StopAtTarget reads the iterate
  StopAtTarget stop(*penalty, y.data(), progress, iterations);
  options.callbacks.push_back(&stop);
  ceres::GradientProblemSolver::Summary summary;
  {
    const QuietCeres quiet;
    ceres::Solve(options, problem, y.data(), &summary);
  }
  out.iterations = static_cast<int>(summary.iterations.size()) - 1;
  out.stop = stop_reason(summary, stop);
  for (const Variable& v : penalty->variables()) {
    if (std::all_of(y.begin() + v.offset, y.begin() + v.offset + v.T.cols(), [](double t) { return t == 0.0; })) continue;
    const Eigen::Vector3d x = penalty->final_position(v, y.data());
    (*moved)[static_cast<std::size_t>(v.global)] = 1;
    for (const Copy& c : copies[static_cast<std::size_t>(v.global)])
      mp.patches[static_cast<std::size_t>(c.patch)].control_points.row(c.local) = x.transpose();
  }
  return out;
}

}  // namespace igaprep::spline::detail
