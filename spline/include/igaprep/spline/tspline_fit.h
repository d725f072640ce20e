#pragma once
// Fit-driven refinement of a T-spline (issue 18, the paper's section 8):
// the element faces that stand for an input surface are fitted to it; the
// boxes of the T-mesh whose faces stay farther than a tolerance from it are
// refined (analysis-suitably, refine_boxes), and the fit is made again in
// the larger space, until every face is within the tolerance or the rounds
// run out. Each round fits from the starting model's geometry (exact in the
// refined space, nestedness), so a round's result depends on its mesh
// alone, not on the fits before it.
//
// The fit is the extraction-form counterpart of fit_model_surface: point
// pairs (a face point and its target) are asked of the caller; every
// control point of a function that does not vanish on the surface's faces
// moves along the faces' normal there by the offsets that solve a linear
// least-squares problem on the pairs, plus a fairing term (the offsets of
// two functions that share a face element pulled together) and a small
// Tikhonov term. Control points of functions on the faces of two surfaces,
// and the interior ones, stay.
#include <Eigen/Core>
#include <functional>
#include <vector>

#include "igaprep/spline/extraction_model.h"
#include "igaprep/spline/side.h"
#include "igaprep/spline/tspline_model.h"

namespace igaprep::spline {

struct ExtractionFitPair {
  int element = -1;
  Side side;                                     // the element's face (ExtractionBoundaryFace::side)
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();  // Bernstein coordinates on it, in side.tangent_directions() order
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
};

// The pairs of one surface (a label) for the current model (e.g. closest
// points both ways: iga_check/extraction_fidelity.h).
using ExtractionFitPairsFn = std::function<std::vector<ExtractionFitPair>(const ExtractionModel& current, int surface)>;

struct ExtractionSurfaceFitOptions {
  int iterations = 4;              // pair / solve rounds
  double smoothing = 0.01;         // fairing weight, relative to the pairs' mean weight per function
  double stop_improvement = 1e-2;  // stop when the rms pair distance changes by less (relative)
};

struct ExtractionSurfaceFitResult {
  std::vector<double> rms;  // rms pair distance before each iteration, then after the last
  int moved_points = 0;     // functions free to move
  double max_move = 0.0;    // largest distance a control point moved
};

// The point of an element face at Bernstein coordinates uv.
Eigen::Vector3d face_point(const ExtractionModel& m, int element, Side side, const Eigen::Vector2d& uv);

ExtractionSurfaceFitResult fit_extraction_surface(ExtractionModel& m, int surface, const ExtractionFitPairsFn& pairs,
                                                  const ExtractionSurfaceFitOptions& options = {});

// Every control point of a function on no surface's faces moves by the
// discrete harmonic extension of the moves from `before` (the same model
// before its faces were fitted): each one's move the mean of the moves of
// the functions it shares an element with. So the elements behind a fitted
// face are not squeezed.
void carry_extraction_moves_inside(ExtractionModel& m, const Eigen::MatrixXd& before);

struct TSplineFitOptions {
  double tolerance = 0.0;  // model units: the largest pair distance allowed on an element face
  int max_rounds = 4;      // refinement rounds at most (0: fit the starting mesh only)
  bool carry_inside = true;  // carry_extraction_moves_inside after each round's fit
  ExtractionSurfaceFitOptions fit;
};

struct TSplineFitRound {
  int functions = 0, elements = 0;
  double max_distance = 0.0;  // largest pair distance after the round's fit
  int elements_over = 0;      // elements with a face farther than the tolerance
  int boxes_refined = 0;      // boxes split after the round (0 for the last)
};

struct TSplineFitResult {
  ExtractionModel model;  // the last round's fitted model
  std::vector<TSplineFitRound> rounds;
  bool reached = false;   // every face within the tolerance
};

// Inputs: the T-spline (refined in place), the surfaces (labels) to fit,
// their pairs. Throws bad_input for a tolerance that is not positive.
TSplineFitResult fit_tspline(TSplineModel& model, const std::vector<int>& surfaces, const ExtractionFitPairsFn& pairs,
                             const TSplineFitOptions& options);

}  // namespace igaprep::spline
