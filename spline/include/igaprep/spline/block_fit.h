#pragma once
// Fitting of sampled hex blocks (param::VolumeParam) as B-spline patches:
// tensor-product interpolation at the Greville abscissae of an open uniform
// knot vector. With interpolation, the control points of a side depend only
// on the samples on that side (the collocation matrix of an open knot vector
// has unit first and last rows), and those of an edge only on the edge's
// samples: neighbours that sample a shared side alike get the same side
// control points up to round-off, which stitch_control_points() then makes
// identical (conforming interfaces, shared edges and corners included).
#include <vector>

#include <Eigen/Core>

#include "igaprep/spline/multipatch.h"

namespace igaprep::spline {

struct BlockFitOptions {
  int degree = 3;
  int elements = 4;  // knot spans per direction
};

// The parameters to sample a block at: the Greville abscissae of the knot
// vector (elements + degree of them, 0 and 1 included).
std::vector<double> block_sample_params(const BlockFitOptions& options);

// Inputs: samples (m^3 x 3, first direction fastest) at block_sample_params
// in each direction. Output: the interpolating B-spline patch (material 0).
// Throws bad_input when the sample count does not match the options.
Patch interpolate_block(const Eigen::MatrixXd& samples, const BlockFitOptions& options);

}  // namespace igaprep::spline
