#include "case_midsurface.h"

#include <algorithm>
#include <fstream>

#include "case_json.h"
#include "igaprep/core/error.h"

namespace igaprep::cli {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& file, const std::string& message) { case_fail(file, message); }

void refuse_unknown(const json& object, const std::vector<std::string>& known, const std::string& where,
                    const std::string& file) {
  refuse_unknown_keys(object, known, where, file);
}

Eigen::Vector3d point3(const json& v, const std::string& where, const std::string& file) {
  if (!v.is_array() || v.size() != 3) fail(file, "'" + where + "' must be a list of three numbers");
  Eigen::Vector3d p;
  for (int i = 0; i < 3; ++i) {
    if (!v[static_cast<std::size_t>(i)].is_number()) fail(file, "'" + where + "' must be a list of three numbers");
    p(i) = v[static_cast<std::size_t>(i)].get<double>();
  }
  return p;
}

}  // namespace

param::MidsurfaceOptions parse_midsurface_options(const json& section, const std::string& file) {
  param::MidsurfaceOptions o;
  if (!section.is_object()) fail(file, "'midsurface' must be an object");
  refuse_unknown(section, {"corners", "cut", "m0", "path_lengths"}, "midsurface", file);
  if (section.contains("cut")) {
    const json& cut = section["cut"];
    if (cut.is_string()) {
      if (cut.get<std::string>() != "auto")
        fail(file, "'midsurface.cut' must be \"auto\", {\"plane\": ...} or {\"loops\": ...}, got \"" +
                       cut.get<std::string>() + "\"");
    } else if (cut.is_object()) {
      refuse_unknown(cut, {"loops", "plane"}, "midsurface.cut", file);
      if (cut.contains("plane") == cut.contains("loops"))
        fail(file, "'midsurface.cut' needs exactly one of 'plane' and 'loops'");
      if (cut.contains("plane")) {
        const json& p = cut["plane"];
        if (!p.is_object()) fail(file, "'midsurface.cut.plane' must be an object with 'point' and 'normal'");
        refuse_unknown(p, {"normal", "point"}, "midsurface.cut.plane", file);
        if (!p.contains("point") || !p.contains("normal"))
          fail(file, "'midsurface.cut.plane' needs 'point' and 'normal'");
        o.cut = param::MidsurfaceOptions::CutKind::Plane;
        o.plane.point = point3(p["point"], "midsurface.cut.plane.point", file);
        o.plane.normal = point3(p["normal"], "midsurface.cut.plane.normal", file);
        if (!(o.plane.normal.norm() > 0.0)) fail(file, "'midsurface.cut.plane.normal' must not be zero");
      } else {
        const json& loops = cut["loops"];
        if (!loops.is_array() || loops.empty())
          fail(file, "'midsurface.cut.loops' must be a non-empty list of lists of vertex indices");
        for (std::size_t l = 0; l < loops.size(); ++l) {
          const std::string where = "midsurface.cut.loops[" + std::to_string(l) + "]";
          if (!loops[l].is_array()) fail(file, "'" + where + "' must be a list of vertex indices");
          std::vector<int> loop;
          for (const json& v : loops[l]) {
            if (!v.is_number_integer() || v.get<long long>() < 0)
              fail(file, "'" + where + "' must hold non-negative integer vertex indices");
            loop.push_back(v.get<int>());
          }
          o.loops.push_back(loop);
        }
        o.cut = param::MidsurfaceOptions::CutKind::Loops;
      }
    } else {
      fail(file, "'midsurface.cut' must be \"auto\" or an object, got " + std::string(cut.type_name()));
    }
  }
  if (section.contains("corners")) {
    const json& c = section["corners"];
    if (!c.is_array()) fail(file, "'midsurface.corners' must be a list of points [x, y, z]");
    for (std::size_t i = 0; i < c.size(); ++i)
      o.corners.push_back(point3(c[i], "midsurface.corners[" + std::to_string(i) + "]", file));
  }
  if (section.contains("m0")) {
    if (!section["m0"].is_number()) fail(file, "'midsurface.m0' must be a number");
    o.m0 = section["m0"].get<double>();
    if (!(o.m0 > 0.0 && o.m0 < 1.0)) fail(file, "'midsurface.m0' must lie in (0, 1)");
  }
  if (section.contains("path_lengths")) {
    if (!section["path_lengths"].is_boolean()) fail(file, "'midsurface.path_lengths' must be true or false");
    o.path_lengths = section["path_lengths"].get<bool>();
  }
  return o;
}

}  // namespace igaprep::cli
