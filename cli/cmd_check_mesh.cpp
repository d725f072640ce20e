// igaprep check-mesh FILE... [--json]: a report per surface, then whether
// the surfaces are nested (outermost first). Exit 1 on any defect.
#include <iostream>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "igaprep/core/error.h"
#include "igaprep/mesh/check_surface.h"
#include "igaprep/mesh/nesting.h"
#include "igaprep/mesh/read_surface.h"

namespace igaprep::cli {

namespace {

// A file that could not be read has no counts or flags: null, not zeros.
nlohmann::json unreadable_json(const std::string& file) {
  nlohmann::json j;
  for (const char* key : {"vertices", "faces", "components", "genus", "closed", "manifold", "oriented",
                          "self_intersections", "volume", "bbox"})
    j[key] = nullptr;
  j["file"] = file;
  j["readable"] = false;
  j["warnings"] = nlohmann::json::array();
  return j;
}

nlohmann::json report_json(const mesh::SurfaceReport& r) {
  return {{"readable", true},{"file", r.file},
          {"vertices", r.vertices},
          {"faces", r.faces},
          {"components", r.components},
          {"genus", r.genus >= 0 ? nlohmann::json(r.genus) : nlohmann::json(nullptr)},
          {"closed", r.closed},
          {"manifold", r.manifold},
          {"oriented", r.oriented},
          {"self_intersections",
           r.self_intersections >= 0 ? nlohmann::json(r.self_intersections) : nlohmann::json(nullptr)},
          {"volume", r.volume},
          {"bbox", {{r.bbox_min.x(), r.bbox_min.y(), r.bbox_min.z()}, {r.bbox_max.x(), r.bbox_max.y(), r.bbox_max.z()}}},
          {"warnings", r.warnings}};
}

int check_mesh(const std::vector<std::string>& files, bool as_json) {
  std::vector<mesh::TriMesh> meshes;
  std::vector<std::string> names;
  nlohmann::json surfaces = nlohmann::json::array();
  std::vector<std::string> errors;
  bool all_readable_and_valid = true;
  for (const std::string& file : files) {
    mesh::SurfaceReport report;
    bool readable = true;
    try {
      mesh::TriMesh m = mesh::read_surface(file);
      report = mesh::check_and_repair_surface(m, file);
      meshes.push_back(std::move(m));
      names.push_back(file);
    } catch (const Error& e) {
      report.file = file;
      report.errors.push_back(e.what());
      readable = false;
    }
    if (!report.ok()) all_readable_and_valid = false;
    errors.insert(errors.end(), report.errors.begin(), report.errors.end());
    if (as_json) {
      surfaces.push_back(readable ? report_json(report) : unreadable_json(file));
    } else if (readable) {
      std::cout << mesh::format_report(report) << "\n";
    } else {
      std::cout << "surface: " << file << "\nunreadable\n\n";
    }
  }
  // Nesting is decided only when every surface is valid and there are two or more.
  nlohmann::json nested = nullptr;
  if (all_readable_and_valid && meshes.size() > 1) {
    const mesh::NestingReport nesting = mesh::check_nesting(meshes, names);
    nested = nesting.nested;
    errors.insert(errors.end(), nesting.errors.begin(), nesting.errors.end());
  }
  if (as_json) {
    std::cout << nlohmann::json{{"surfaces", surfaces}, {"nested", nested}, {"errors", errors}}.dump(2) << "\n";
  } else {
    if (nested.is_null()) {
      std::cout << "nesting: " << (meshes.size() < 2 && all_readable_and_valid ? "one surface, nothing to nest"
                                                                                 : "not decided (defective surfaces)")
                << "\n";
    } else {
      std::cout << "nesting: " << (nested.get<bool>() ? "nested, outermost first" : "NOT nested") << "\n";
    }
    for (const auto& e : errors) std::cerr << "error: " << e << "\n";
  }
  return errors.empty() ? 0 : 1;
}

}  // namespace

void add_check_mesh_command(CLI::App& app) {
  auto* sub = app.add_subcommand("check-mesh", "Check closed triangle surfaces and their nesting (outermost first)");
  auto files = std::make_shared<std::vector<std::string>>();
  auto as_json = std::make_shared<bool>(false);
  sub->add_option("files", *files, "STL, OBJ, OFF or PLY surfaces, outermost first")->required();
  sub->add_flag("--json", *as_json, "Print one JSON object instead of tables (docs/cli.md)");
  set_body(sub, [files, as_json] { return check_mesh(*files, *as_json); });
}

}  // namespace igaprep::cli
