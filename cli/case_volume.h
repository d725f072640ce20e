#pragma once
// The "decomposition" and "fit" sections of a case file (docs/case-format.md):
//   "decomposition": {"strategy": 2, "theta": 0.785, "w0": 0.75, "inset": 0.3, "smoothing": 5,
//                     "blend": 0.5, "crest_reach": 1.0},
//   "fit": {"degree": 3, "elements": 6, "oversample": 2,
//           "jacobian_target": 0.35, "jacobian_sweeps": 40, "jacobian_points": 5}
#include <string>

#include <nlohmann/json.hpp>

#include "igaprep/param/volume_param.h"
#include "igaprep/spline/block_fit.h"
#include "igaprep/spline/optimize_jacobian.h"

namespace igaprep::cli {

param::VolumeParamOptions parse_decomposition_options(const nlohmann::json& section, const std::string& file);
spline::BlockFitOptions parse_fit_options(const nlohmann::json& section, const std::string& file);
// The same section's jacobian_* keys (spline/optimize_jacobian.h; target 0: off).
spline::JacobianOptimizationOptions parse_jacobian_options(const nlohmann::json& section, const std::string& file);

}  // namespace igaprep::cli
