#include "igaprep/pipeline/fit_retry.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "igaprep/core/text.h"
#include "igaprep/iga_check/criteria.h"
#include "stage_timer.h"

namespace igaprep::pipeline {

namespace {

// Whether every failed criterion is one a finer fit can change (not
// conformity, not watertightness).
bool only_resolution_failed(const iga_check::CheckReport& r) {
  return std::all_of(r.criteria.begin(), r.criteria.end(), [](const iga_check::Criterion& c) {
    return c.passed || c.name == "jacobian" || c.name == "fidelity" || c.name == "volume";
  });
}

// The largest |value| / limit of the fidelity and volume criteria.
double largest_excess(const iga_check::CheckReport& r) {
  double worst = 0.0;
  for (const iga_check::Criterion& c : r.criteria)
    if ((c.name == "fidelity" || c.name == "volume") && c.checked && c.limit > 0.0)
      worst = std::max(worst, std::abs(c.value) / c.limit);
  return worst;
}

// The failed fidelity figure over its limit when fidelity is the one
// failed criterion; 0 otherwise.
double fidelity_alone_excess(const iga_check::CheckReport& r) {
  double excess = 0.0;
  for (const iga_check::Criterion& c : r.criteria) {
    if (c.passed) continue;
    if (c.name != "fidelity" || !(c.limit > 0.0)) return 0.0;
    excess = std::abs(c.value) / c.limit;
  }
  return excess;
}

// d refuses a finer fit; where fidelity alone failed within kFaceFitReach
// and the faces were not fitted yet, it becomes a retry that fits them.
FitRetryDecision or_fit_faces(FitRetryDecision d, const Check& check, int elements, bool faces_fitted) {
  const double excess = fidelity_alone_excess(check.report);
  if (faces_fitted || !(excess > 0.0) || excess > kFaceFitReach) return d;
  d.retry = true;
  d.fit_faces = true;
  d.elements = elements;
  d.reason = text("no finer fit: %s; fidelity alone failed, %.2f times its limit", d.reason.c_str(), excess);
  return d;
}

// Whether a round of the repair made the check better (better_attempt), or
// as good in its counts with a larger smallest scaled Jacobian and no
// larger excess of fidelity or volume: a fold raised towards positive that
// the next round can open (torus3 at 6 elements: -0.008 -> -0.001 on the
// same element).
bool round_improves(const Check& after, const Check& before) {
  if (better_attempt(after, before)) return true;
  return after.report.passed == before.report.passed && uncertified_elements(after) == uncertified_elements(before) &&
         largest_excess(after.report) <= largest_excess(before.report) &&
         after.figures.min_scaled_jacobian > before.figures.min_scaled_jacobian;
}

// Up to kNegativeElementRounds rounds of the repair aimed at the points
// where the check found det J negative, each kept when round_improves; each
// round is a "repair" summary line, the repair's time with its check's.
void repair_negative_elements(const Case& c, const Surfaces& surfaces, const Decomposition& d, FitAttempt& m,
                              Observer& observer) {
  if (!(c.jacobian.target > 0.0) || !repair_skip_reason(m.vp).empty()) return;
  // Every round's points stay among the samples, so that a fold opened in
  // one round is not closed again by the next.
  std::vector<std::pair<int, Eigen::Vector3d>> witnesses;
  auto stray = [&] {
    const CheckFigures& f = m.check.figures;
    return f.negative > 0 && static_cast<double>(f.negative) <= kNegativeElementShare * static_cast<double>(f.elements);
  };
  for (int round = 1; round <= kNegativeElementRounds && stray(); ++round) {
    StageTimer timer;
    auto say = [&](const std::string& line) { observer.stage_finished({"repair", timer.seconds(), line, {}}); };
    Fit fit = m.fit;
    const auto found = negative_points(m.check.report);
    witnesses.insert(witnesses.end(), found.begin(), found.end());
    const spline::JacobianOptimizationResult r = repair_at_negative_points(c, d, m.vp, fit.model, witnesses, observer);
    const std::string what = text("repair at the check's %ld negative elements (round %d): %d patches, their lowest "
                                  "sample %.3f -> %.3f",
                                  m.check.figures.negative, round, r.focus_patches, r.focus_min_before,
                                  r.focus_min_after);
    if (r.focus_patches == 0 || !r.focus_kept) {
      say(what + ": not raised, the model stays");
      return;
    }
    Check check = check_stage(fit.model, surfaces.inputs, c.check, observer);
    const bool better = round_improves(check, m.check);
    say(what + text("; the check then: %ld elements not certified positive (was %ld), smallest scaled Jacobian %.3f "
                    "(was %.3f), %s",
                    uncertified_elements(check), uncertified_elements(m.check), check.figures.min_scaled_jacobian,
                    m.check.figures.min_scaled_jacobian, better ? "kept" : "not kept"));
    if (!better) return;
    m.fit = std::move(fit);
    m.check = std::move(check);
  }
}

// The next attempt fits the faces on the input surfaces to them, and says so.
void fit_faces_next(Case& next, const FitRetryDecision& why, const std::function<void(const std::string&)>& say) {
  next.surface_fit.iterations = kFaceFitIterations;
  next.surface_fit.smoothing = kFaceFitSmoothing;
  say(why.reason + text(": the faces on the input surfaces are fitted to them ('fit.surface_iterations' %d, "
                        "'fit.surface_smoothing' %g)",
                        kFaceFitIterations, kFaceFitSmoothing));
}

}  // namespace

double folded_sample_share(const param::VolumeParam& vp) {
  const double m = static_cast<double>(vp.params.size());
  const double face_cells = static_cast<double>(vp.blocks.size()) * (m - 1.0) * (m - 1.0);
  return face_cells > 0.0 ? vp.folded_cells / face_cells : 0.0;
}

std::string repair_skip_reason(const param::VolumeParam& vp) {
  const double share = folded_sample_share(vp);
  if (!(share > kRepairFoldedShare)) return "";
  return text("the blocks' folded sample cells are %.1f %% of their face cells (more than %.0f %%): the folds are in "
              "the fitted samples, which moving control points cannot undo; the check says where",
              100.0 * share, 100.0 * kRepairFoldedShare);
}

FitRetryDecision decide_fit_retry(const Check& check, const param::VolumeParam& vp, int elements, bool faces_fitted,
                                  const CaseFitRetry& settings) {
  FitRetryDecision d;
  if (check.report.passed) {
    d.reason = "the check passed";
    return d;
  }
  const std::string failed = iga_check::failed_criterion_names(check.report.criteria);
  if (!only_resolution_failed(check.report)) {
    d.reason = "the check failed on " + failed + ", which a finer fit does not change";
    return d;
  }
  if (settings.max_elements <= elements) {
    d.reason = text("the fit has the most elements per direction allowed ('fit.max_elements' %d)",
                    settings.max_elements);
    return d;
  }
  const double share = folded_sample_share(vp);
  if (share > kRetryFoldedShare) {
    d.reason = text("the blocks' folded sample cells are %.2f %% of their face cells (more than %.1f %%): a finer fit "
                    "would follow the folds",
                    100.0 * share, 100.0 * kRetryFoldedShare);
    return or_fit_faces(d, check, elements, faces_fitted);
  }
  // 1.5 times as many, or as many as max_model_elements allows.
  int next = std::min(settings.max_elements, std::max(elements + 1, (3 * elements + 1) / 2));
  const auto blocks = static_cast<long long>(vp.blocks.size());
  while (next > elements && blocks * next * next * next > settings.max_model_elements) --next;
  if (next <= elements) {
    const int more = elements + 1;
    d.reason = text("%d elements per direction would make %lld elements, more than 'fit.max_model_elements' %lld",
                    more, blocks * more * more * more, settings.max_model_elements);
    return d;
  }
  // Between samples a fit cuts T1 like chords, whose distance falls like the
  // square of their length: a figure further over its limit than that
  // would bring back is not worth the finer fit's time.
  const double reach = (static_cast<double>(next) / elements) * (static_cast<double>(next) / elements);
  const double excess = largest_excess(check.report);
  if (excess > reach) {
    d.reason = text("fidelity or volume is %.2f times its limit, and %d elements per direction would bring it to "
                    "%.2f times at best (the distance falls like the square of the element size)",
                    excess, next, excess / reach);
    return or_fit_faces(d, check, elements, faces_fitted);
  }
  d.retry = true;
  d.elements = next;
  d.reason = text("the check failed on %s with %d elements per direction and the blocks' folded sample cells are "
                  "%.2f %% of their face cells",
                  failed.c_str(), elements, 100.0 * share);
  return d;
}

long uncertified_elements(const Check& check) {
  const CheckFigures& f = check.figures;
  return f.negative + f.undecided + (check.report.allow_degenerate ? 0 : f.degenerate);
}

bool better_attempt(const Check& a, const Check& b) {
  if (a.report.passed != b.report.passed) return a.report.passed;
  const long ua = uncertified_elements(a), ub = uncertified_elements(b);
  if (ua != ub) return ua < ub;
  return largest_excess(a.report) < largest_excess(b.report);
}

FitAttempt best_fit_attempt(const Case& c, const std::function<MadeAttempt(const Case&)>& make,
                            const std::function<void(const std::string&)>& say) {
  FitAttempt best;
  Case next = c;
  for (;;) {
    MadeAttempt made = make(next);
    ++best.attempts;
    if (best.attempts > 1 && !better_attempt(made.check, best.check)) {
      say(text("kept the fit with %d elements per direction: the one with %d is not better (%ld against %ld "
               "elements not certified positive)",
               best.settings.fit.elements, next.fit.elements, uncertified_elements(made.check),
               uncertified_elements(best.check)));
      // A finer fit that did not help leaves the kept one's fidelity to the
      // faces fitted to the input, once.
      FitRetryDecision no_finer;
      no_finer.reason = text("the fit with %d elements per direction was not better", next.fit.elements);
      const bool faces_tried = next.surface_fit.iterations > 0 || best.settings.surface_fit.iterations > 0;
      const FitRetryDecision faces = or_fit_faces(no_finer, best.check, best.settings.fit.elements, faces_tried);
      if (!faces.retry) return best;
      next = best.settings;
      fit_faces_next(next, faces, say);
      continue;
    }
    best.settings = next;
    best.rectangles = made.vp.rectangles;
    best.boundary_segments = made.vp.crests;
    best.vp = std::move(made.vp);
    best.fit = std::move(made.fit);
    best.check = std::move(made.check);
    const FitRetryDecision decision =
        decide_fit_retry(best.check, best.vp, next.fit.elements, next.surface_fit.iterations > 0, c.fit_retry);
    if (!decision.retry) {
      if (!best.check.report.passed) say("no finer fit: " + decision.reason);
      return best;
    }
    if (decision.fit_faces) {
      fit_faces_next(next, decision, say);
      continue;
    }
    say(decision.reason + text(": the blocks are sampled and fitted again with %d elements per direction "
                               "('fit.max_elements' %d)",
                               decision.elements, c.fit_retry.max_elements));
    next.fit.elements = decision.elements;
  }
}

FitAttempt fit_and_check(const Case& c, const Surfaces& surfaces, const Decomposition& d, Observer& observer) {
  std::optional<param::VolumeParam> last;  // the blocks of the last attempt
  int last_elements = 0;
  auto say = [&](const std::string& line) { observer.stage_finished({"retry", 0.0, line, {}}); };
  auto make = [&](const Case& attempt) {
    MadeAttempt m;
    const bool same_samples = last && last_elements == attempt.fit.elements;
    m.vp = same_samples ? *last : param_stage(attempt, surfaces, d, observer);
    last = m.vp;
    last_elements = attempt.fit.elements;
    m.fit = fit_stage(attempt, surfaces, d, m.vp, observer);
    m.check = check_stage(m.fit.model, surfaces.inputs, attempt.check, observer);
    return m;
  };
  // The rounds come after the finer fits: a finer fit that passes has a
  // better minimum than a fold opened just past 0 (torus_genus3: certified
  // by the rounds at 6 elements with a smallest scaled Jacobian of 0.016, at
  // 9 elements it passes with 0.336).
  FitAttempt best = best_fit_attempt(c, make, say);
  if (!best.check.report.passed) repair_negative_elements(best.settings, surfaces, d, best, observer);
  return best;
}

}  // namespace igaprep::pipeline
