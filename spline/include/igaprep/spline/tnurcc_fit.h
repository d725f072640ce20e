#pragma once
// Fitting a cage so that its limit surface follows a target surface: point
// pairs (a limit location and the target point it should reach) are asked
// of the caller for the current cage, then the cage points solve the linear
// least-squares problem on OpenSubdiv's limit stencils, with a small
// umbrella-Laplacian term on the update so that points no pair pulls stay
// in place and the cage stays fair. Repeated: the pairs follow the surface.
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
  double smoothing = 1e-3;           // weight of the update's Laplacian, per pair and cage point
  double stop_improvement = 1e-3;    // stop when the rms distance improves by less (relative)
  LimitOptions limit;
};

struct CageFitResult {
  Cage cage;
  std::vector<double> rms;  // rms pair distance before each iteration, then after the last
  int iterations = 0;
};

CageFitResult fit_cage(const Cage& start, const FitPairsFn& pairs, const CageFitOptions& options = {});

}  // namespace igaprep::spline
