#include "case_volume.h"

#include "case_json.h"

namespace igaprep::cli {

param::VolumeParamOptions parse_decomposition_options(const nlohmann::json& s, const std::string& file) {
  if (!s.is_object()) case_fail(file, "'decomposition' must be an object");
  refuse_unknown_keys(s, {"blend", "crest_reach", "inset", "sliding_uv", "smoothing", "strategy", "surface_degree", "theta", "w0"}, "decomposition", file);
  param::VolumeParamOptions o;
  o.strategy = static_cast<int>(case_number(s, "strategy", o.strategy, 1, 2, "decomposition", file));
  if (s.contains("strategy") && !s["strategy"].is_number_integer())
    case_fail(file, "'decomposition.strategy' must be 1 or 2");
  o.theta = case_number(s, "theta", o.theta, 0.05, 1.5, "decomposition", file);
  o.w0 = case_number(s, "w0", o.w0, 0.0, 1.0, "decomposition", file);
  if (s.contains("smoothing") && !s["smoothing"].is_number_integer())
    case_fail(file, "'decomposition.smoothing' must be an integer");
  o.smoothing = static_cast<int>(case_number(s, "smoothing", o.smoothing, 0, 100, "decomposition", file));
  o.inset = case_number(s, "inset", o.inset, 0.05, 0.95, "decomposition", file);
  o.crest_reach = case_number(s, "crest_reach", o.crest_reach, 0.1, 2.0, "decomposition", file);
  o.blend = case_number(s, "blend", o.blend, 0.01, 4.0, "decomposition", file);
  if (s.contains("surface_degree") && !s["surface_degree"].is_number_integer())
    case_fail(file, "'decomposition.surface_degree' must be an integer");
  o.surface_degree = static_cast<int>(case_number(s, "surface_degree", o.surface_degree, 0, 12, "decomposition", file));
  if (s.contains("sliding_uv")) {
    if (!s["sliding_uv"].is_boolean()) case_fail(file, "'decomposition.sliding_uv' must be true or false");
    o.sliding_uv = s["sliding_uv"].get<bool>();
  }
  return o;
}

spline::BlockFitOptions parse_fit_options(const nlohmann::json& s, const std::string& file) {
  if (!s.is_object()) case_fail(file, "'fit' must be an object");
  refuse_unknown_keys(s, {"degree", "elements", "jacobian_points", "jacobian_sweeps", "jacobian_target", "oversample"},
                     "fit", file);
  spline::BlockFitOptions o;
  for (const char* key : {"degree", "elements", "oversample"})
    if (s.contains(key) && !s[key].is_number_integer()) case_fail(file, std::string("'fit.") + key + "' must be an integer");
  o.degree = static_cast<int>(case_number(s, "degree", o.degree, 1, 5, "fit", file));
  o.elements = static_cast<int>(case_number(s, "elements", o.elements, 1, 32, "fit", file));
  o.oversample = static_cast<int>(case_number(s, "oversample", o.oversample, 1, 8, "fit", file));
  return o;
}

spline::JacobianOptimizationOptions parse_jacobian_options(const nlohmann::json& s, const std::string& file) {
  spline::JacobianOptimizationOptions o;
  for (const char* key : {"jacobian_points", "jacobian_sweeps"})
    if (s.contains(key) && !s[key].is_number_integer()) case_fail(file, std::string("'fit.") + key + "' must be an integer");
  o.target = case_number(s, "jacobian_target", o.target, 0.0, 0.9, "fit", file);
  o.sweeps = static_cast<int>(case_number(s, "jacobian_sweeps", o.sweeps, 0, 1000, "fit", file));
  o.points = static_cast<int>(case_number(s, "jacobian_points", o.points, 2, 9, "fit", file));
  return o;
}

}  // namespace igaprep::cli
