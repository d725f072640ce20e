#include <filesystem>

#include <nlohmann/json.hpp>

#include "igaprep/pipeline/case.h"

namespace igaprep::pipeline {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string relative(const std::string& path, const std::string& to) {
  return to.empty() ? path : fs::path(path).lexically_relative(to).string();
}

json surfaces_json(const Case& c, const std::string& relative_to) {
  json surfaces = json::array();
  for (const auto& s : c.surfaces) {
    json e;
    if (s.offset_of) {
      e["offset_of"] = *s.offset_of;
      e["inward"] = s.inward;
    } else if (s.mesh) {
      e["in_memory"] = true;
    } else {
      e["file"] = relative(s.file, relative_to);
    }
    e["label"] = s.label;
    if (s.remesh == CaseSurface::Remesh::Off) e["remesh"] = false;
    if (s.remesh == CaseSurface::Remesh::Length) e["remesh"] = s.remesh_length;
    surfaces.push_back(e);
  }
  return surfaces;
}

json validation_json(const CaseValidation& v) {
  return {{"enabled", v.enabled}, {"coarse_refine", v.coarse_refine}, {"fine_refine", v.fine_refine},
          {"patches", v.patches}, {"solver", iga_check::linear_solver_name(v.solver)},
          {"finer_when_missed", v.finer_when_missed}};
}

json check_json(const iga_check::CheckOptions& o) {
  return {{"fidelity_limit", 100.0 * o.fidelity_limit}, {"volume_limit", 100.0 * o.volume_limit}};
}

json reduce_json(const ReduceSettings& s) {
  return s.tolerance > 0.0 ? json{{"tolerance", s.tolerance}} : json{{"relative_tolerance", s.relative_tolerance}};
}

json tspline_json(const TSplineSettings& s) {
  json j = s.tolerance > 0.0 ? json{{"tolerance", s.tolerance}} : json{{"relative_tolerance", s.relative_tolerance}};
  j["rounds"] = s.rounds;
  return j;
}

json tnurcc_json(const TnurccSettings& s) {
  return {{"crease_angle", s.crease_angle}, {"fit_iterations", s.fit_iterations},
          {"samples_per_face", s.samples_per_face}, {"vtu_per_face", s.vtu_per_face},
          {"equal_intervals", s.equal_intervals}, {"smoothing", s.smoothing}};
}

bool check_is_default(const iga_check::CheckOptions& o) {
  const iga_check::CheckOptions d;
  return o.fidelity_limit == d.fidelity_limit && o.volume_limit == d.volume_limit;
}

json selection_json(const CaseSideSelection& w) {
  json e{{"label", w.label}};
  if (w.box) e["box"] = {{(*w.box)[0].x(), (*w.box)[0].y(), (*w.box)[0].z()}, {(*w.box)[1].x(), (*w.box)[1].y(), (*w.box)[1].z()}};
  return e;
}

json load_case_json(const CaseLoadCase& lc) {
  json fix = json::array(), pressure = json::array(), traction = json::array();
  for (const auto& f : lc.fix) {
    json e = selection_json(f.where);
    std::string comp;
    for (int d = 0; d < 3; ++d)
      if (f.components[d]) comp += static_cast<char>('x' + d);
    e["components"] = comp;
    fix.push_back(e);
  }
  for (const auto& p : lc.pressure) {
    json e = selection_json(p.where);
    e["value"] = p.value;
    pressure.push_back(e);
  }
  for (const auto& t : lc.traction) {
    json e = selection_json(t.where);
    e["value"] = {t.value.x(), t.value.y(), t.value.z()};
    traction.push_back(e);
  }
  json force = json::array();
  for (const auto& f : lc.force) {
    json e = selection_json(f.where);
    e["value"] = {f.value.x(), f.value.y(), f.value.z()};
    force.push_back(e);
  }
  json out{{"fix", fix}, {"pressure", pressure}, {"traction", traction}, {"force", force},
           {"body_force", {lc.body_force.x(), lc.body_force.y(), lc.body_force.z()}}, {"refine", lc.refine},
           {"solver", iga_check::linear_solver_name(lc.solver)}};
  if (const auto& r = lc.rotation)
    out["rotation"] = {{"density", r->density}, {"angular_velocity", r->angular_velocity},
                       {"axis", {r->axis.x(), r->axis.y(), r->axis.z()}},
                       {"point", {r->point.x(), r->point.y(), r->point.z()}}};
  return out;
}

// Every stage option, defaults included.
void add_stage_options(const Case& c, json& root) {
  json mid{{"path_lengths", c.midsurface.path_lengths}};
  if (c.midsurface.cut == param::MidsurfaceOptions::CutKind::Plane) {
    const auto& p = c.midsurface.plane;
    mid["cut"] = {{"plane", {{"point", {p.point.x(), p.point.y(), p.point.z()}},
                             {"normal", {p.normal.x(), p.normal.y(), p.normal.z()}}}}};
  } else if (c.midsurface.cut == param::MidsurfaceOptions::CutKind::Loops) {
    mid["cut"] = {{"loops", c.midsurface.loops}};
  } else if (c.midsurface.cut == param::MidsurfaceOptions::CutKind::Waypoints) {
    json loops = json::array();
    for (const auto& loop : c.midsurface.waypoints) {
      json points = json::array();
      for (const auto& p : loop) points.push_back({p.x(), p.y(), p.z()});
      loops.push_back(points);
    }
    mid["cut"] = {{"waypoints", loops}};
  } else {
    mid["cut"] = "auto";
  }
  json corners = json::array();
  for (const auto& p : c.midsurface.corners) corners.push_back({p.x(), p.y(), p.z()});
  if (!corners.empty()) mid["corners"] = corners;
  root["midsurface"] = mid;
  const auto& v = c.volume;
  root["decomposition"] = {{"inset", c.base.inset}, {"rim_reach", c.base.rim_reach}, {"smoothing", c.base.smoothing}, {"sliding_uv", c.base.sliding_uv},
                           {"max_aspect", c.base.max_aspect},
                           {"strategy", v.strategy}, {"theta", v.theta}, {"blend", v.blend},
                           {"crest_reach", v.crest_reach}, {"surface_degree", v.surface_degree},
                           {"corner_share", v.corner_share},
                           {"lid_relax_rings", v.lid_relax_rings},
                           {"spread_deviation", c.auto_spread_deviation ? json("auto") : json(v.spread_deviation)},
                           {"cover_rounds", c.cover_rounds}};
  if (v.w0 >= 0.0) root["decomposition"]["w0"] = v.w0;  // absent: midway, at least 0.75
  root["fit"] = {{"degree", c.fit.degree}, {"elements", c.fit.elements}, {"max_elements", c.fit_retry.max_elements},
                 {"max_model_elements", c.fit_retry.max_model_elements}, {"oversample", c.fit.oversample},
                 {"surface_iterations", c.surface_fit.iterations}, {"surface_smoothing", c.surface_fit.smoothing},
                 {"jacobian_target", c.jacobian.target}, {"jacobian_iterations", c.jacobian.iterations},
                 {"jacobian_sweeps", c.jacobian.sweeps},
                 {"jacobian_points", c.jacobian.points}};
  root["export"] = c.export_formats;
  root["check"] = check_json(c.check);
  root["validation"] = validation_json(c.validation);
  if (c.reduce) root["reduce"] = reduce_json(*c.reduce);
  if (c.tnurcc) root["tnurcc"] = tnurcc_json(*c.tnurcc);
  if (c.tspline) root["tspline"] = tspline_json(*c.tspline);
  if (c.load_case) root["load_case"] = load_case_json(*c.load_case);
}

bool validation_is_default(const CaseValidation& v) {
  const CaseValidation d;
  return v.enabled == d.enabled && v.coarse_refine == d.coarse_refine && v.fine_refine == d.fine_refine &&
         v.patches == d.patches && v.solver == d.solver && v.finer_when_missed == d.finer_when_missed;
}

}  // namespace

std::string case_json(const Case& c, const std::string& relative_to, bool all_options) {
  json root;
  root["name"] = c.name;
  root["surfaces"] = surfaces_json(c, relative_to);
  json materials = json::array();
  for (const auto& m : c.materials)
    materials.push_back({{"name", m.name}, {"young_modulus", m.young_modulus}, {"poisson_ratio", m.poisson_ratio}});
  root["materials"] = materials;
  root["output"] = relative(c.output_dir, relative_to);
  root["tetmesh"] = {{"radius_edge_ratio", c.tetmesh.radius_edge_ratio}, {"max_volume", c.tetmesh.max_volume}};
  if (all_options || c.tetmesh.max_tets != mesh::TetgenOptions{}.max_tets) root["tetmesh"]["max_tets"] = c.tetmesh.max_tets;
  if (all_options) {
    add_stage_options(c, root);
  } else {
    if (c.export_formats != Case{}.export_formats) root["export"] = c.export_formats;
    if (!check_is_default(c.check)) root["check"] = check_json(c.check);
    if (!validation_is_default(c.validation)) root["validation"] = validation_json(c.validation);
    if (c.reduce) root["reduce"] = reduce_json(*c.reduce);
    if (c.tnurcc) root["tnurcc"] = tnurcc_json(*c.tnurcc);
  if (c.tspline) root["tspline"] = tspline_json(*c.tspline);
  }
  return root.dump(2) + "\n";
}

}  // namespace igaprep::pipeline
