#pragma once
// Evenly spread shell columns. Where a thick part of the solid is reached
// from a narrow core face (the propeller's hub, crossed by M at mid-height),
// w falls off exponentially away from M and the streamlines of -grad w fan
// out: a region of T1 many samples wide is reached from between two
// neighbouring samples of the face, and the shell block's face on T1 is a
// chord across it. Here the face's sample parameters are moved so that the
// streamlines' ends on T1 are evenly spaced (docs/decomposition.md).
#include <array>
#include <cstddef>
#include <functional>
#include <vector>

#include <Eigen/Core>

namespace igaprep::param {

struct SpreadOptions {
  // A row of ends is spread only when its largest gap is more than this
  // many times its mean gap (the built-in models' rows: at most 2.3; the
  // propeller's hub: up to 8).
  double uneven_ratio = 3.0;
  // A row is spread as well when the streamline from the middle of a gap
  // ends farther than this (model units) from the cubic through the four
  // nearest ends: a part of T1 that bulges out between two samples (a
  // kitten's ear), which the samples cut off without making the gaps
  // uneven; gaps are then halved until their middle ends lie this close to
  // their chords. 0: off.
  double chord_deviation = 0.0;
  // Rounds of moving a spread face's inner parameters towards ends that are
  // each the mean of their neighbours' (0: off). Spreading rows and columns
  // one by one makes the ends even along each, not across, and a fan's ends
  // can still fold on T1 (docs/decomposition.md, "Spread columns").
  int end_smoothing = 20;
  int refinements = 12;  // halvings of a parameter interval, at most
  int per_gap = 4;       // the curve of ends is refined to this many chords per even gap
};

// The interval of the ascending params (0 first, 1 last) that holds x:
// params[i] <= x <= params[i + 1], and x's fraction w in it. Exact at the
// parameters (w = 0 at params[i], w = 1 at the last one), so that values
// interpolated there are the samples bit for bit.
struct ParamCell {
  std::size_t i;
  double w;
};
ParamCell param_cell(const std::vector<double>& params, double x);

// Inputs: the curve s -> end(s) for s in [0, 1], its ends at the ascending
// params (0 first, 1 last). Output: parameters from 0 to 1 at which the ends
// are evenly spaced by chord length along the curve (refined adaptively
// between the given ends), or params itself when the given ends are not
// uneven (SpreadOptions::uneven_ratio) and no gap bulges
// (SpreadOptions::chord_deviation). Deterministic: the same curve and
// ends give the same parameters, so neighbouring faces that share an edge
// agree on it.
std::vector<double> even_end_params(const std::function<Eigen::Vector3d(double)>& end,
                                    const std::vector<double>& params, const std::vector<Eigen::Vector3d>& ends,
                                    const SpreadOptions& options = {});

// The same over a face: m x m sample points (s, t) of the unit square, first
// index fastest, from the grid params x params. Every row (t = params[j])
// is spread along s, then every column through the rows' new points (a
// polyline in (s, t)) along its length; folded cells are untangled; if any
// point moved, the inner points are then moved so that their ends form a
// smooth grid (SpreadOptions::end_smoothing); the square's sides marked fixed
// (bottom t = 0, right s = 1, top t = 1, left s = 0) keep their points. On
// a side a result depends only on the ends along it. end(p): the end of
// the streamline from the face at p; ends: at the grid points.
std::vector<Eigen::Vector2d> spread_face_params(const std::function<Eigen::Vector3d(const Eigen::Vector2d&)>& end,
                                                const std::vector<double>& params,
                                                const std::vector<Eigen::Vector3d>& ends,
                                                const std::array<bool, 4>& fixed_sides = {},
                                                const SpreadOptions& options = {});

}  // namespace igaprep::param
