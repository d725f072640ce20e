#pragma once
// A finer fit where the check fails for want of resolution: the blocks are
// sampled and fitted again with about 1.5 times as many elements per
// direction (fewer where CaseFitRetry::max_model_elements allows no more),
// as long as the samples themselves are sound. A fit of folded
// samples only follows the folds more closely when it is finer (the
// propeller at 4 and 8 elements per direction: 128 and 952 negative
// elements), so a run whose sample cells are folded in more than a small
// share is not refitted (docs/decomposition.md, "A finer fit").
#include <functional>
#include <string>

#include "igaprep/param/volume_param.h"
#include "igaprep/pipeline/case.h"
#include "igaprep/pipeline/check.h"
#include "igaprep/pipeline/observer.h"
#include "igaprep/pipeline/surfaces.h"
#include "igaprep/pipeline/volume.h"

namespace igaprep::pipeline {

// Folded sample cells above this share of the blocks' face cells say the
// samples, not the fit's resolution, make the model fail. Counted against a
// face's cells, not a block's: folds lie in sheets (along T1, where
// streamlines tear), so their count grows like a face's cells when the
// sampling is finer (torus_genus3: 0.34 % at 6 and 0.33 % at 9 elements per
// direction; the propeller 6.2 % at 4 and 11 % at 8; the pelvis 31 % at 6).
constexpr double kRetryFoldedShare = 0.01;

// Folded sample cells above this share of the blocks' face cells say the
// Jacobian repair cannot certify the model: the folds are in the data it
// fits, and it moves control points within a neighbour distance. Below it
// the repair pays (the propeller at 6.2 %: 841 -> 300 negative elements);
// above it, it only costs (the pelvis at 31 %: more than 40 minutes, stopped
// by hand, docs/validation.md; the genus-4 statuette).
constexpr double kRepairFoldedShare = 0.2;

// Folded sample cells per cell of a block's face.
double folded_sample_share(const param::VolumeParam& vp);

// Why the Jacobian repair is not worth making on these samples (more than
// kRepairFoldedShare of their face cells folded), or "" when it is.
std::string repair_skip_reason(const param::VolumeParam& vp);

// Where fidelity alone failed by at most this many times its limit and a
// finer fit would not help (folded samples, or out of its reach), the faces
// on the input surfaces are fitted to them instead (fit_model_surface.h):
// the kitten's ear, 0.537 % of the diagonal at 6 elements with 1.18 % of
// its sample cells folded, came to 0.388 % with every element positive.
constexpr double kFaceFitReach = 2.0;
// That fit's settings: the kitten's measured ones (docs/decomposition.md,
// "Fitting the faces to the input").
constexpr int kFaceFitIterations = 20;
constexpr double kFaceFitSmoothing = 0.003;

// Rounds of the repair aimed at the points where the check found det J
// negative (repair_at_negative_points) after the kept attempt's check found
// negative elements, each kept when the check then counts fewer elements
// not certified positive, or as many with a larger smallest scaled
// Jacobian and fidelity and volume no worse (the hand: 25 negative
// elements between the repair's samples, docs/decomposition.md section 6).
constexpr int kNegativeElementRounds = 4;
// The rounds run only while the negative elements are at most this share
// of the model's: stray folds between the repair's samples (the hand: 25
// of 170,640, 0.015 %). Above it the folds are the samples' (the propeller
// at 4 elements: 454 of 33,536, 1.4 %, where four rounds left 200 for
// fidelity 1.30 -> 1.98 % and six minutes).
constexpr double kNegativeElementShare = 0.001;

struct FitRetryDecision {
  bool retry = false;
  int elements = 0;        // per direction for the next attempt (when retry)
  bool fit_faces = false;  // the next attempt fits the faces to the input (kFaceFit*)
  std::string reason;      // why or why not, one clause for the run's summary
};

// A retry is made when the check failed on the Jacobian, fidelity or volume
// only, the samples are sound (kRetryFoldedShare), the caps allow the finer
// count, and fidelity and volume are within reach of their limits: at most
// (finer / present elements)^2 times them. Where the samples or the reach
// refuse it, fidelity alone failed within kFaceFitReach, and the faces were
// not fitted yet, the retry keeps the elements and fits the faces.
// Inputs: the check of the attempt just made, its sampled blocks, the
// elements per direction it used, whether its faces were fitted to the
// input, the case's settings.
FitRetryDecision decide_fit_retry(const Check& check, const param::VolumeParam& vp, int elements, bool faces_fitted,
                                  const CaseFitRetry& settings);

// Elements of a check not certified positive (degenerate ones count unless
// the check allows them).
long uncertified_elements(const Check& check);

// Whether attempt a is better than b: a passed check first, then fewer
// elements not certified positive, then the smaller largest excess of a
// fidelity or volume figure over its limit.
bool better_attempt(const Check& a, const Check& b);

struct FitAttempt {
  Case settings;     // the case with the kept attempt's elements per direction
  Fit fit;
  Check check;
  int attempts = 0;  // fits made, the kept one among them
  int rectangles = 0, boundary_segments = 0;  // of the layout its blocks were built on
  param::VolumeParam vp;                      // the sampled blocks it was fitted to
};

// One attempt as the loop sees it: the fit, its check and the sampled
// blocks it was fitted to.
struct MadeAttempt {
  Fit fit;
  Check check;
  param::VolumeParam vp;
};

// The loop of fit_and_check for any way of making an attempt (the tests
// give their own): make(case) makes one with the case's elements per
// direction; say(line) hears each decision after a failed check.
FitAttempt best_fit_attempt(const Case& c, const std::function<MadeAttempt(const Case&)>& make,
                            const std::function<void(const std::string&)>& say);

// The param, fit and check stages; then again with more elements per
// direction (or the faces fitted) while decide_fit_retry says so and each
// attempt is better than the best so far; an attempt with the elements of
// the last one reuses its sampled blocks. Each decision after a failed check is a "retry"
// summary line (none when the first check passes). When the best attempt
// fails with negative elements, rounds of the repair at their points follow
// (kNegativeElementRounds, a "repair" and a "check" line each). Output: the
// best attempt.
FitAttempt fit_and_check(const Case& c, const Surfaces& surfaces, const Decomposition& d, Observer& observer);

}  // namespace igaprep::pipeline
