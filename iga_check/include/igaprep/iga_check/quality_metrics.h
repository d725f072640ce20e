#pragma once
// Pointwise quality of the parameterization at a dense set of points per
// element: in each direction the union of a regular sub-grid (corners
// included) and the p+1 Gauss points, taken as a tensor grid. Per point: det J, the scaled Jacobian det J / (|x_u| |x_v| |x_w|)
// (spline::scaled_jacobian: 1 for orthogonal columns, <= 0 where inverted, 0
// where a column vanishes) and the Frobenius condition
// number |J|_F |J^-1|_F / 3 (1 for a conformal J, infinite where singular).
#include <Eigen/Core>
#include <array>
#include <vector>

#include "igaprep/spline/multipatch.h"
#include "igaprep/spline/scaled_jacobian.h"

namespace igaprep::iga_check {

using spline::scaled_jacobian;  // the optimizer's too (spline/optimize_jacobian.h)
double condition_number(const Eigen::Matrix3d& J);  // +infinity when J is singular

struct QualityOptions {
  int grid = 5;              // sub-grid points per direction per element (>= 2, includes corners)
  bool gauss = true;         // add the (p+1) Gauss points per direction
  int histogram_bins = 20;
  int worst_count = 10;      // worst elements kept (by smallest scaled Jacobian)
};

struct Histogram {
  double lo = 0.0, hi = 0.0;    // range; bin b covers [lo + b w, lo + (b+1) w)
  std::vector<long> counts;     // the last bin includes hi; values outside are clamped
};

struct MetricStats {
  double min = 0.0, max = 0.0, mean = 0.0;  // condition: over finite values
  long count = 0;                           // points counted (condition: finite ones)
  Histogram histogram;
};

// The worst point of an element.
struct QualityPoint {
  int patch = -1;
  std::array<int, 3> element{{0, 0, 0}};
  Eigen::Vector3d uvw = Eigen::Vector3d::Zero();  // patch parameters
  Eigen::Vector3d x = Eigen::Vector3d::Zero();    // physical point
  double det_j = 0.0, scaled_jacobian = 0.0, condition = 0.0;
};

struct PatchQuality {
  int patch = -1;
  long points = 0;
  MetricStats det_j, scaled_jacobian, condition;
  long singular_points = 0;  // points where J is singular (condition infinite)
};

struct QualityReport {
  std::vector<PatchQuality> patches;
  PatchQuality overall;             // all patches together (patch = -1)
  std::vector<QualityPoint> worst;  // worst elements, smallest scaled Jacobian first
};

// Inputs: model, options. Output: per-patch and overall statistics. The
// histograms of scaled Jacobian use [-1, 1]; those of det J and condition the
// model-wide range, so patches compare bin by bin.
QualityReport quality_metrics(const spline::MultiPatch& mp, const QualityOptions& options = {});

}  // namespace igaprep::iga_check
