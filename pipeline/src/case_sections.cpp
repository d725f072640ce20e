#include "case_sections.h"

#include "igaprep/core/error.h"
#include "json_reader.h"

namespace igaprep::pipeline {

using nlohmann::json;

namespace {

void read_cut_plane(const json& p, const std::string& file, param::MidsurfaceOptions& o) {
  ObjectReader r(p, "midsurface.cut.plane", file);
  const json* point = r.find("point");
  const json* normal = r.find("normal");
  r.refuse_unknown();
  if (!point || !normal) r.fail("'midsurface.cut.plane' needs 'point' and 'normal'");
  o.cut = param::MidsurfaceOptions::CutKind::Plane;
  o.plane.point = read_vector3(*point, "midsurface.cut.plane.point", file);
  o.plane.normal = read_vector3(*normal, "midsurface.cut.plane.normal", file);
  if (!(o.plane.normal.norm() > 0.0)) r.fail("'midsurface.cut.plane.normal' must not be zero");
}

void read_cut_loops(const json& loops, const ObjectReader& r, param::MidsurfaceOptions& o) {
  if (!loops.is_array() || loops.empty())
    r.fail("'midsurface.cut.loops' must be a non-empty list of lists of vertex indices");
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const std::string where = "midsurface.cut.loops[" + std::to_string(l) + "]";
    if (!loops[l].is_array()) r.fail("'" + where + "' must be a list of vertex indices");
    std::vector<int> loop;
    for (const json& v : loops[l]) {
      if (!v.is_number_integer() || v.get<long long>() < 0)
        r.fail("'" + where + "' must hold non-negative integer vertex indices");
      loop.push_back(v.get<int>());
    }
    o.loops.push_back(loop);
  }
  o.cut = param::MidsurfaceOptions::CutKind::Loops;
}

// "waypoints": a list of loops, each a list of points [x, y, z].
void read_cut_waypoints(const json& loops, const std::string& file, const ObjectReader& r,
                        param::MidsurfaceOptions& o) {
  if (!loops.is_array() || loops.empty())
    r.fail("'midsurface.cut.waypoints' must be a non-empty list of loops, each a list of points [x, y, z]");
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const std::string where = "midsurface.cut.waypoints[" + std::to_string(l) + "]";
    if (!loops[l].is_array() || loops[l].size() < 3) r.fail("'" + where + "' must be a list of at least 3 points");
    std::vector<Eigen::Vector3d> loop;
    for (std::size_t i = 0; i < loops[l].size(); ++i)
      loop.push_back(read_vector3(loops[l][i], where + "[" + std::to_string(i) + "]", file));
    o.waypoints.push_back(std::move(loop));
  }
  o.cut = param::MidsurfaceOptions::CutKind::Waypoints;
}

void read_cut(const json& cut, const std::string& file, param::MidsurfaceOptions& o) {
  if (cut.is_string()) {
    if (cut.get<std::string>() != "auto")
      throw bad_input(file + ": 'midsurface.cut' must be \"auto\", {\"plane\": ...}, {\"loops\": ...} or {\"waypoints\": ...}, got \"" +
                      cut.get<std::string>() + "\"");
    return;
  }
  if (!cut.is_object())
    throw bad_input(file + ": 'midsurface.cut' must be \"auto\" or an object, got " + std::string(cut.type_name()));
  ObjectReader r(cut, "midsurface.cut", file);
  const json* plane = r.find("plane");
  const json* loops = r.find("loops");
  const json* waypoints = r.find("waypoints");
  r.refuse_unknown();
  if ((plane != nullptr) + (loops != nullptr) + (waypoints != nullptr) != 1)
    r.fail("'midsurface.cut' needs exactly one of 'plane', 'loops' and 'waypoints'");
  if (plane) read_cut_plane(*plane, file, o);
  else if (loops) read_cut_loops(*loops, r, o);
  else read_cut_waypoints(*waypoints, file, r, o);
}

}  // namespace

param::MidsurfaceOptions read_midsurface_section(const json& section, const std::string& file) {
  ObjectReader r(section, "midsurface", file);
  param::MidsurfaceOptions o;
  if (r.find("m0"))
    r.fail("'midsurface.m0' is no longer read: the base surface M is M0trim inset in its (u, v) domain "
           "(set 'decomposition.inset' instead)");
  if (const json* cut = r.find("cut")) read_cut(*cut, file, o);
  if (const json* c = r.find("corners")) {
    if (!c->is_array()) r.fail("'midsurface.corners' must be a list of points [x, y, z]");
    for (std::size_t i = 0; i < c->size(); ++i)
      o.corners.push_back(read_vector3((*c)[i], "midsurface.corners[" + std::to_string(i) + "]", file));
  }
  o.path_lengths = r.boolean("path_lengths", o.path_lengths);
  r.refuse_unknown();
  return o;
}

void read_decomposition_section(const json& section, const std::string& file, param::BaseSurfaceOptions& base,
                                param::VolumeParamOptions& volume, bool& auto_spread_deviation,
                                int& cover_rounds) {
  ObjectReader r(section, "decomposition", file);
  base.inset = r.number_in("inset", base.inset, 0.05, 0.95);
  base.rim_reach = r.number_in("rim_reach", base.rim_reach, 0.0, 1e3);
  if (base.rim_reach > 0.0 && base.rim_reach < 1.0)
    r.fail("'decomposition.rim_reach' must be 0 (no cap) or at least 1, got " + std::to_string(base.rim_reach));
  base.smoothing = r.integer("smoothing", base.smoothing, 0, 100);
  base.sliding_uv = r.boolean("sliding_uv", base.sliding_uv);
  base.max_aspect = r.number_in("max_aspect", base.max_aspect, 0.0, 100.0);
  if (base.max_aspect > 0.0 && base.max_aspect < 1.0)
    r.fail("'decomposition.max_aspect' must be 0 (no cuts) or at least 1, got " + std::to_string(base.max_aspect));
  volume.strategy = r.integer("strategy", volume.strategy, 1, 2);
  volume.theta = r.number_in("theta", volume.theta, 0.05, 1.5);
  volume.w0 = r.number_in("w0", volume.w0, 0.0, 1.0);
  volume.crest_reach = r.number_in("crest_reach", volume.crest_reach, 0.1, 2.0);
  volume.blend = r.number_in("blend", volume.blend, 0.01, 4.0);
  volume.surface_degree = r.integer("surface_degree", volume.surface_degree, 0, 12);
  volume.corner_share = r.number_in("corner_share", volume.corner_share, 0.0, 0.5);
  volume.lid_relax_rings = r.integer("lid_relax_rings", volume.lid_relax_rings, 0, 64);
  const json* spread = r.find("spread_deviation");
  if (spread && spread->is_string()) {
    if (spread->get<std::string>() != "auto")
      r.fail("'decomposition.spread_deviation' must be \"auto\" or a number in [0, 0.1], got \"" +
             spread->get<std::string>() + "\"");
    auto_spread_deviation = true;
  } else if (spread) {
    volume.spread_deviation = r.number_in("spread_deviation", volume.spread_deviation, 0.0, 0.1);
    auto_spread_deviation = false;
  }
  cover_rounds = r.integer("cover_rounds", cover_rounds, 0, 4);
  r.refuse_unknown();
}

void read_fit_section(const json& section, const std::string& file, spline::BlockFitOptions& fit,
                      CaseFitRetry& retry, spline::SurfaceFitOptions& surface,
                      spline::JacobianOptimizationOptions& jacobian) {
  ObjectReader r(section, "fit", file);
  fit.degree = r.integer("degree", fit.degree, 1, 5);
  fit.elements = r.integer("elements", fit.elements, 1, 32);
  // An explicit element count is kept unless max_elements asks for more.
  retry.max_elements = r.find("elements") ? fit.elements : retry.max_elements;
  retry.max_elements = r.integer("max_elements", retry.max_elements, 1, 32);
  retry.max_model_elements = r.integer("max_model_elements", static_cast<int>(retry.max_model_elements), 1, 100000000);
  fit.oversample = r.integer("oversample", fit.oversample, 1, 8);
  surface.iterations = r.integer("surface_iterations", surface.iterations, 0, 100);
  surface.smoothing = r.number_in("surface_smoothing", surface.smoothing, 0.0, 1e6);
  jacobian.target = r.number_in("jacobian_target", jacobian.target, 0.0, 0.9);
  jacobian.iterations = r.integer("jacobian_iterations", jacobian.iterations, 0, 100000);
  jacobian.sweeps = r.integer("jacobian_sweeps", jacobian.sweeps, 0, 1000);
  jacobian.points = r.integer("jacobian_points", jacobian.points, 2, 9);
  r.refuse_unknown();
}

}  // namespace igaprep::pipeline
