#pragma once
// Fitting a cage so that its limit surface follows a target surface: point
// pairs (a limit location and the target point it should reach) are asked
// of the caller for the current cage, then the cage points solve the linear
// least-squares problem on OpenSubdiv's limit stencils plus a fairing term
// (the umbrella Laplacian of the cage points, weighted): it holds points no
// pair pulls and keeps the surface from following a faceted mesh's kinks.
// Repeated: the pairs follow the surface.
#include <Eigen/Core>
#include <functional>
#include <vector>

#include "igaprep/spline/tnurcc_cage.h"
#include "igaprep/spline/tnurcc_limit.h"

namespace igaprep::spline {

struct FitPair {
  LimitLocation at;
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
};

// The pairs for the current cage (e.g. closest points both ways:
// iga_check/tnurcc_fidelity.h).
using FitPairsFn = std::function<std::vector<FitPair>(const Cage& current)>;

struct CageFitOptions {
  int iterations = 8;
  double smoothing = 0.1;            // weight of the fairing term, per pair and cage point
  double stop_improvement = 1e-3;    // stop when the rms distance changes by less (relative)
  LimitOptions limit;
};

struct CageFitResult {
  Cage cage;
  std::vector<double> rms;  // rms pair distance before each iteration, then after the last
  int iterations = 0;
};

CageFitResult fit_cage(const Cage& start, const FitPairsFn& pairs, const CageFitOptions& options = {});

}  // namespace igaprep::spline
