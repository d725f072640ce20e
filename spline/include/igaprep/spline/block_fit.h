#pragma once
// Fitting of sampled hex blocks (param::VolumeParam) as B-spline patches with
// conforming sides: least squares on an open uniform knot vector, in the
// order corners, edges, faces, interior (seed paper, section 7): the corner
// control points are the corner samples, each edge is fitted to its own
// samples with its corners fixed, each face to its samples with its edges
// fixed, the interior with all six faces fixed. A side's control points thus
// depend only on the samples on that side, so two blocks that sample a shared
// side alike get the same control points up to round-off, which
// stitch_control_points() (find_interfaces.h) then makes identical: shared
// faces, edges and corners conform.
#include <vector>

#include <Eigen/Core>

#include "igaprep/spline/multipatch.h"

namespace igaprep::spline {

struct BlockFitOptions {
  int degree = 3;
  int elements = 6;    // knot spans per direction
  int oversample = 2;  // samples per control-point interval (1: interpolation at the Greville points)
};

// The parameters to sample a block at, in each direction: the Greville
// abscissae of the knot vector with oversample - 1 points between
// consecutive ones; 0 and 1 included.
std::vector<double> block_sample_params(const BlockFitOptions& options);

// Inputs: samples (m^3 x 3, first direction fastest) at block_sample_params
// in each direction. Output: the fitted B-spline patch (material 0). Throws
// bad_input when the sample count does not match the options.
Patch fit_block(const Eigen::MatrixXd& samples, const BlockFitOptions& options);

}  // namespace igaprep::spline
