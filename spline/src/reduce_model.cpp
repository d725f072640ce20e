#include "igaprep/spline/reduce_model.h"

#include <Eigen/QR>
#include <algorithm>
#include <iterator>
#include <limits>
#include <set>

#include "igaprep/core/error.h"
#include "igaprep/spline/evaluate.h"
#include "igaprep/spline/knot_families.h"
#include "igaprep/spline/knot_removal.h"
#include "igaprep/spline/knot_vector.h"
#include "igaprep/spline/multipatch_topology.h"
#include "igaprep/spline/refine.h"

namespace igaprep::spline {

namespace {

// The coarse rows from the fine ones (nc x nf): first and last row kept, the
// others the least-squares solution of fine = R coarse, R the insertion matrix.
Eigen::MatrixXd projection_operator(const std::vector<double>& fine, const std::vector<double>& coarse, int p) {
  const int nf = basis_count(fine, p), nc = basis_count(coarse, p);
  std::vector<double> refined;
  Eigen::MatrixXd R;  // nf x nc
  insert_knots_1d(coarse, p, Eigen::MatrixXd::Identity(nc, nc), missing_knots(fine, coarse), &refined, &R);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(nc, nf);
  A(0, 0) = 1.0;
  A(nc - 1, nf - 1) = 1.0;
  if (nc > 2) {
    const Eigen::MatrixXd inner = R.block(1, 1, nf - 2, nc - 2);
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(nf - 2, nf);  // fine interior rows minus the kept ends' share
    rhs.block(0, 1, nf - 2, nf - 2).setIdentity();
    rhs.col(0) -= R.block(1, 0, nf - 2, 1);
    rhs.col(nf - 1) -= R.block(1, nc - 1, nf - 2, 1);
    A.block(1, 0, nc - 2, nf) = inner.colPivHouseholderQr().solve(rhs);
  }
  return A;
}

// The bound of a reduced patch against its original: the control-point
// change in the original's basis; where that exceeds `limit`, the smaller
// change in the basis with every span halved once more (still a bound, and
// closer to the true distance, since control nets converge to the volume
// under refinement).
double patch_bound(const Patch& original, const Patch& reduced, double limit) {
  const Patch same_basis = refine_to_knots(reduced, original.knots);
  const double bound = change_bound(original, same_basis);
  if (bound <= limit) return bound;
  return std::min(bound, change_bound(refine_uniformly(original), refine_uniformly(same_basis)));
}

long element_count(const Patch& p) {
  long n = 1;
  for (int d = 0; d < 3; ++d) n *= static_cast<long>(unique_knots(p.knots[d]).size()) - 1;
  return n;
}

// Largest distance between two patches on one domain, at n^3 parameters.
double sampled_distance(const Patch& a, const Patch& b, int n) {
  std::array<std::vector<double>, 3> params;
  for (int d = 0; d < 3; ++d) {
    const double lo = a.knots[d][a.degrees[d]], hi = a.knots[d][a.count(d)];
    for (int i = 0; i < n; ++i) params[d].push_back(lo + (hi - lo) * i / (n - 1));
  }
  const Eigen::MatrixXd xa = evaluate_grid_points(a, grid_basis(a, params, 0));
  const Eigen::MatrixXd xb = evaluate_grid_points(b, grid_basis(b, params, 0));
  return (xa - xb).rowwise().norm().maxCoeff();
}

// Points that an interface shares are made bit-identical (the projections of
// the two patches agree up to rounding).
void make_shared_points_identical(MultiPatch& mp) {
  const GlobalNumbering g = global_numbering(mp);
  std::vector<std::pair<int, int>> first(static_cast<std::size_t>(g.count), {-1, -1});
  for (std::size_t p = 0; p < mp.patches.size(); ++p)
    for (std::size_t i = 0; i < g.global[p].size(); ++i) {
      auto& f = first[static_cast<std::size_t>(g.global[p][i])];
      if (f.first < 0) {
        f = {static_cast<int>(p), static_cast<int>(i)};
        continue;
      }
      const Patch& src = mp.patches[static_cast<std::size_t>(f.first)];
      Patch& dst = mp.patches[p];
      dst.control_points.row(static_cast<long>(i)) = src.control_points.row(f.second);
      if (dst.rational()) dst.weights(static_cast<long>(i)) = src.rational() ? src.weights(f.second) : 1.0;
    }
}

// Candidates are ordered by the quick bound; those within this many
// tolerances of it are tried (the tight bound was up to 6 times smaller on
// sphere2 at 12 elements).
constexpr double kQuickReach = 10.0;

// The kept knots of every family and the patches they give.
class Reducer {
 public:
  Reducer(const MultiPatch& mp, double tolerance) : mp_(mp), tolerance_(tolerance), families_(knot_families(mp)) {
    member_of_.resize(3 * mp.patches.size());
    for (std::size_t f = 0; f < families_.size(); ++f) {
      kept_.emplace_back(family_parameters(mp.patches[static_cast<std::size_t>(families_[f].members[0].patch)],
                                           families_[f].members[0].direction, false)
                             .size(),
                         char{1});
      std::set<int> patches;
      for (const FamilyMember& m : families_[f].members) {
        member_of_[static_cast<std::size_t>(3 * m.patch + m.direction)] = {static_cast<int>(f), m.reversed};
        patches.insert(m.patch);
      }
      patches_of_.emplace_back(patches.begin(), patches.end());
    }
    reduced_ = mp.patches;
  }

  const std::vector<KnotFamily>& families() const { return families_; }
  int removals() const { return static_cast<int>(log_.size()); }
  int undone() const { return undone_; }
  const std::vector<Patch>& reduced() const { return reduced_; }

  // Greedy passes: every candidate measured, cheapest first, each made when
  // every patch it touches stays within the tolerance.
  void remove_knots(const ProgressCallback& progress) {
    for (bool removed = true; removed;) {
      removed = false;
      std::vector<Candidate> candidates = measured_candidates(progress);
      std::stable_sort(candidates.begin(), candidates.end(),
                       [](const Candidate& a, const Candidate& b) { return a.cost < b.cost; });
      for (const Candidate& c : candidates) removed = try_removal(c) || removed;
    }
  }

  // The caller's check on every changed patch; a refused patch has the
  // latest removal that touched it undone until it passes.
  void enforce(const ReducedPatchCheck& check) {
    std::set<int> pending;
    for (std::size_t p = 0; p < reduced_.size(); ++p)
      if (reduced_[p].knots != mp_.patches[p].knots) pending.insert(static_cast<int>(p));
    while (!pending.empty()) {
      std::set<int> next;
      for (int p : pending) {
        if (check(p, reduced_[static_cast<std::size_t>(p)])) continue;
        const int entry = latest_removal_touching(p);
        if (entry < 0) continue;  // back to the original patch
        for (int q : undo(entry)) next.insert(q);
      }
      pending = std::move(next);
    }
  }

 private:
  struct Candidate {
    int family = 0;
    std::vector<int> knots;  // family knot indices removed together
    double cost = 0.0;
  };
  struct Removal {
    int family = 0;
    std::vector<int> knots;
    bool undone = false;
  };

  std::array<std::vector<double>, 3> kept_knots(int patch) const {
    const Patch& p = mp_.patches[static_cast<std::size_t>(patch)];
    std::array<std::vector<double>, 3> out;
    for (int d = 0; d < 3; ++d) {
      const auto [family, reversed] = member_of_[static_cast<std::size_t>(3 * patch + d)];
      const std::vector<char>& kept = kept_[static_cast<std::size_t>(family)];
      const std::vector<double>& U = p.knots[d];
      const int deg = p.degrees[d], n = p.count(d), m = n - deg - 1;
      out[d].assign(U.begin(), U.begin() + deg + 1);
      for (int k = 0; k < m; ++k)
        if (kept[static_cast<std::size_t>(reversed ? m - 1 - k : k)]) out[d].push_back(U[static_cast<std::size_t>(deg + 1 + k)]);
      out[d].insert(out[d].end(), U.begin() + n, U.end());
    }
    return out;
  }

  // How a trial measures: the bound patch_bound tightens above `tighten_above`,
  // and the trial stops at the first patch whose bound passes `stop_above`.
  struct Measure {
    double tighten_above, stop_above;
  };
  Measure exact() const { return {tolerance_, tolerance_}; }
  Measure quick() const { return {kNever, kQuickReach * tolerance_}; }
  static constexpr double kNever = std::numeric_limits<double>::infinity();

  // The patches of a family with its present kept knots; the largest bound.
  double trial(int family, const Measure& m, std::vector<std::pair<int, Patch>>* patches) const {
    double worst = 0.0;
    for (int p : patches_of_[static_cast<std::size_t>(family)]) {
      const Patch& original = mp_.patches[static_cast<std::size_t>(p)];
      Patch r = project_patch(original, kept_knots(p));
      const double b = patch_bound(original, r, m.tighten_above);
      worst = std::max(worst, b);
      if (patches) patches->emplace_back(p, std::move(r));
      if (worst > m.stop_above) break;
    }
    return worst;
  }

  void set_kept(const Candidate& c, bool value) {
    for (int k : c.knots) kept_[static_cast<std::size_t>(c.family)][static_cast<std::size_t>(k)] = value;
  }

  std::vector<Candidate> measured_candidates(const ProgressCallback& progress) {
    std::vector<Candidate> all;
    for (std::size_t f = 0; f < families_.size(); ++f) {
      if (!families_[f].consistent) continue;
      const int m = static_cast<int>(kept_[f].size());
      for (int k = 0; k < m; ++k) {
        if (!kept_[f][static_cast<std::size_t>(k)]) continue;
        Candidate c{static_cast<int>(f), {k}, 0.0};
        if (families_[f].self_reversed) {
          if (m - 1 - k < k) continue;
          if (m - 1 - k > k) c.knots.push_back(m - 1 - k);
        }
        all.push_back(c);
      }
    }
    Progress bar("reduce", all.size(), progress);
    std::vector<Candidate> affordable;
    for (std::size_t i = 0; i < all.size(); ++i) {
      set_kept(all[i], false);
      all[i].cost = trial(all[i].family, quick(), nullptr);
      set_kept(all[i], true);
      if (all[i].cost <= quick().stop_above) affordable.push_back(all[i]);
      bar.update(i + 1);
    }
    return affordable;
  }

  bool try_removal(const Candidate& c) {
    for (int k : c.knots)
      if (!kept_[static_cast<std::size_t>(c.family)][static_cast<std::size_t>(k)]) return false;
    set_kept(c, false);
    std::vector<std::pair<int, Patch>> patches;
    if (trial(c.family, exact(), &patches) > tolerance_) {
      set_kept(c, true);
      return false;
    }
    for (auto& [p, patch] : patches) reduced_[static_cast<std::size_t>(p)] = std::move(patch);
    log_.push_back({c.family, c.knots, false});
    return true;
  }

  int latest_removal_touching(int patch) const {
    for (int e = static_cast<int>(log_.size()) - 1; e >= 0; --e) {
      const Removal& r = log_[static_cast<std::size_t>(e)];
      if (r.undone) continue;
      const auto& ps = patches_of_[static_cast<std::size_t>(r.family)];
      if (std::binary_search(ps.begin(), ps.end(), patch)) return e;
    }
    return -1;
  }

  // Puts an entry's knots back; returns the patches that changed.
  std::vector<int> undo(int entry) {
    Removal& r = log_[static_cast<std::size_t>(entry)];
    r.undone = true;
    ++undone_;
    set_kept({r.family, r.knots, 0.0}, true);
    std::vector<std::pair<int, Patch>> patches;
    trial(r.family, {kNever, kNever}, &patches);  // fewer knots removed: within the bound again
    std::vector<int> changed;
    for (auto& [p, patch] : patches) {
      changed.push_back(p);
      reduced_[static_cast<std::size_t>(p)] = std::move(patch);
    }
    return changed;
  }

  const MultiPatch& mp_;
  const double tolerance_;
  std::vector<KnotFamily> families_;
  std::vector<std::vector<char>> kept_;               // per family, per family knot: still there
  std::vector<std::pair<int, bool>> member_of_;       // per (patch, direction): family, reversed
  std::vector<std::vector<int>> patches_of_;          // per family: its patches, increasing
  std::vector<Patch> reduced_;
  std::vector<Removal> log_;
  int undone_ = 0;
};

}  // namespace

Patch project_patch(const Patch& patch, const std::array<std::vector<double>, 3>& knots) {
  Patch out = patch;
  out.displacement.resize(0, 0);
  for (int d = 0; d < 3; ++d) {
    if (knots[d] == patch.knots[d]) continue;
    const Eigen::MatrixXd A = projection_operator(patch.knots[d], knots[d], patch.degrees[d]);
    const Eigen::MatrixXd rows = A * patch_rows(out, d);
    out.knots[d] = knots[d];
    set_patch_rows(&out, d, rows, static_cast<int>(rows.rows()));
  }
  return out;
}

ModelReduction reduce_model(const MultiPatch& mp, const ModelReductionOptions& options,
                            const ReducedPatchCheck& check) {
  if (!(options.tolerance >= 0.0)) throw bad_input("reduce: the tolerance must be a distance >= 0");
  if (options.samples_per_direction < 2) throw bad_input("reduce: at least 2 samples per direction");
  validate_multipatch(mp);
  Reducer reducer(mp, options.tolerance);
  reducer.remove_knots(options.progress);
  if (check) reducer.enforce(check);

  ModelReduction r;
  r.model = mp;
  r.model.patches = reducer.reduced();
  r.model.has_solution = false;
  r.model.strain_energy = r.model.max_displacement = 0.0;
  make_shared_points_identical(r.model);
  r.families = static_cast<int>(reducer.families().size());
  for (const KnotFamily& f : reducer.families()) r.inconsistent_families += f.consistent ? 0 : 1;
  r.knots_removed = reducer.removals() - reducer.undone();
  r.removals_undone = reducer.undone();
  r.control_points_before = control_point_count(mp);
  r.control_points_after = control_point_count(r.model);
  for (std::size_t p = 0; p < mp.patches.size(); ++p) {
    const Patch& a = mp.patches[p];
    const Patch& b = r.model.patches[p];
    r.elements_before += element_count(a);
    r.elements_after += element_count(b);
    r.bound = std::max(r.bound, patch_bound(a, b, 0.0));
    r.measured = std::max(r.measured, sampled_distance(a, b, options.samples_per_direction));
    r.samples += static_cast<long>(options.samples_per_direction) * options.samples_per_direction *
                 options.samples_per_direction;
  }
  return r;
}

}  // namespace igaprep::spline
