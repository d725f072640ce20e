#pragma once
// The stage sections of a case file (docs/case-format.md), each read with an
// ObjectReader that refuses unknown keys and values out of range:
//   "midsurface": {"cut": "auto" | {"plane": {"point", "normal"}} | {"loops": [[i, ...], ...]},
//                  "corners": [[x, y, z], ...], "path_lengths": true}
//   "decomposition": {"strategy": 2, "theta": 1.1, "w0": 0.75 (absent: midway), "inset": 0.3, "smoothing": 5,
//                     "sliding_uv": true, "max_aspect": 2, "blend": 1.0, "crest_reach": 1.0, "surface_degree": 6,
//                     "corner_share": 0, "lid_relax_rings": 0, "spread_deviation": "auto" | number}
//   "fit": {"degree": 3, "elements": 6, "oversample": 2,
//           "jacobian_target": 0.35, "jacobian_iterations": 200, "jacobian_sweeps": 40,
//           "jacobian_points": 5}
#include <string>

#include <nlohmann/json.hpp>

#include "igaprep/pipeline/case.h"

namespace igaprep::pipeline {

param::MidsurfaceOptions read_midsurface_section(const nlohmann::json& section, const std::string& file);
// The decomposition section holds the base surface's keys and the volume's.
void read_decomposition_section(const nlohmann::json& section, const std::string& file, param::BaseSurfaceOptions& base,
                                param::VolumeParamOptions& volume, bool& auto_spread_deviation,
                                int& cover_rounds);
void read_fit_section(const nlohmann::json& section, const std::string& file, spline::BlockFitOptions& fit,
                      CaseFitRetry& retry, spline::SurfaceFitOptions& surface,
                      spline::JacobianOptimizationOptions& jacobian);

}  // namespace igaprep::pipeline
