#pragma once
// Fitting the faces of a model that stand for one input surface (boundary
// sides labelled with it, material interfaces lying on it) to that surface,
// after the volume fit: the blocks' samples leave parts of a real input
// uncovered (an ear, a rim) and the fitted faces cut corners there. Point
// pairs (a face point and the target it should reach) are asked of the
// caller for the current model; each free control point of those faces then
// moves along the faces' outward normal there (free moves re-spaced the nets
// along the surface and sheared the elements behind them), by the offsets
// that solve a linear least-squares problem on the faces' basis functions
// plus a fairing term (the umbrella Laplacian of the offsets over the faces'
// control nets). Repeated: the pairs follow the faces. A point shared by
// several patches moves once (global numbering): interfaces stay conforming.
//
// carry_moves_inside then moves the other control points by the discrete
// harmonic extension of the faces' moves over the patches' control nets, so
// the elements next to the surface are not squeezed.
#include <Eigen/Core>
#include <functional>
#include <utility>
#include <vector>

#include "igaprep/spline/multipatch.h"
#include "igaprep/spline/side.h"

namespace igaprep::spline {

struct SurfaceFitPair {
  int patch = -1;
  Side side;                                       // a face of the surface being fitted
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();    // on boundary_surface(patch, side)
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
};

// The pairs for the current model (e.g. closest points both ways:
// iga_check/surface_fit_pairs.h).
using SurfaceFitPairsFn = std::function<std::vector<SurfaceFitPair>(const MultiPatch& current)>;

struct SurfaceFitOptions {
  // 0: off (the pipeline's default: on the built-in models it changes little
  // and costs Jacobians; docs/decomposition.md, "Fitting the faces to the input").
  int iterations = 0;
  double smoothing = 0.01;          // weight of the fairing term, per pair and control point
  double stop_improvement = 1e-2;   // stop when the rms pair distance changes by less (relative)
};

struct SurfaceFitResult {
  std::vector<double> rms;  // rms pair distance before each iteration, then after the last
  int iterations = 0;
  int moved_points = 0;     // distinct control points that were free to move
  double max_move = 0.0;    // largest distance a control point moved
};

// Inputs: the model with interfaces and labelled boundaries (find_interfaces,
// label_sides); the surface (a label index); sides (patch, side) whose
// control points must stay (collapsed sides). Control points that also lie
// on a face of another surface stay.
SurfaceFitResult fit_model_surface(MultiPatch& mp, int surface, const SurfaceFitPairsFn& pairs,
                                   const std::vector<std::pair<int, Side>>& fixed_sides,
                                   const SurfaceFitOptions& options = {});

// Every control point that lies on no face of any surface (no labelled
// boundary side, no interface with a surface) and on none of `fixed_sides`
// moves by the discrete harmonic extension of the moves from `before` (the
// same model before the surfaces were fitted) to `mp`: each free point's
// move is the mean of its control-net neighbours' moves.
void carry_moves_inside(MultiPatch& mp, const MultiPatch& before, const std::vector<std::pair<int, Side>>& fixed_sides);

}  // namespace igaprep::spline
