#include "case_file.h"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "case_midsurface.h"
#include "case_volume.h"
#include "igaprep/core/error.h"

namespace igaprep::cli {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Reads keys of one JSON object and refuses any it does not know.
class ObjectReader {
 public:
  ObjectReader(const json& object, std::string where, std::string file)
      : object_(object), where_(std::move(where)), file_(std::move(file)) {
    if (!object_.is_object()) fail(where_.empty() ? "the case must be a JSON object" : "'" + where_ + "' must be an object");
  }

  const json* find(const std::string& key) {
    known_.insert(key);
    auto it = object_.find(key);
    return it == object_.end() ? nullptr : &*it;
  }
  double number(const std::string& key, double fallback) {
    const json* v = find(key);
    if (!v) return fallback;
    if (!v->is_number()) fail("'" + path(key) + "' must be a number, got " + v->type_name());
    return v->get<double>();
  }
  double required_number(const std::string& key) {
    if (!object_.contains(key)) fail("missing key '" + path(key) + "'");
    return number(key, 0.0);
  }
  std::string string(const std::string& key, const std::string& fallback) {
    const json* v = find(key);
    if (!v) return fallback;
    if (!v->is_string()) fail("'" + path(key) + "' must be a string, got " + v->type_name());
    return v->get<std::string>();
  }
  std::string path(const std::string& key) const { return where_.empty() ? key : where_ + "." + key; }
  // Call after reading every key: any other key is an error.
  void refuse_unknown() {
    for (auto it = object_.begin(); it != object_.end(); ++it) {
      if (known_.count(it.key())) continue;
      std::string list;
      for (const auto& k : known_) list += (list.empty() ? "" : ", ") + k;
      fail("unknown key '" + path(it.key()) + "' (known here: " + list + ")");
    }
  }
  [[noreturn]] void fail(const std::string& message) const { throw bad_input(file_ + ": " + message); }

 private:
  const json& object_;
  std::string where_;
  std::string file_;
  std::set<std::string> known_;
};

CaseSurface read_surface_entry(const json& entry, int index, const fs::path& folder, const std::string& file) {
  const std::string where = "surfaces[" + std::to_string(index) + "]";
  CaseSurface s;
  if (entry.is_string()) {
    s.file = entry.get<std::string>();
  } else {
    ObjectReader r(entry, where, file);
    s.file = r.string("file", "");
    s.label = r.string("label", "");
    if (const json* of = r.find("offset_of")) {
      if (!of->is_number_integer()) r.fail("'" + r.path("offset_of") + "' must be an integer surface index");
      s.offset_of = of->get<int>();
      s.inward = r.required_number("inward");
    } else if (r.find("inward")) {
      r.fail("'" + r.path("inward") + "' needs 'offset_of' (the surface to offset)");
    }
    r.refuse_unknown();
  }
  if (s.file.empty() == !s.offset_of.has_value())
    throw bad_input(file + ": '" + where + "' needs exactly one of 'file' or 'offset_of'");
  if (s.offset_of) {
    if (*s.offset_of < 0 || *s.offset_of >= index)
      throw bad_input(file + ": '" + where + ".offset_of' must name an earlier surface (0.." +
                      std::to_string(index - 1) + ")");
    if (!(s.inward > 0.0)) throw bad_input(file + ": '" + where + ".inward' must be positive");
    if (s.label.empty()) s.label = "offset" + std::to_string(index);
  } else {
    const fs::path resolved = fs::path(s.file).is_absolute() ? fs::path(s.file) : folder / s.file;
    if (!fs::exists(resolved))
      throw bad_input(file + ": '" + where + "' names a file that does not exist: " + resolved.string());
    s.file = resolved.lexically_normal().string();
    if (s.label.empty()) s.label = fs::path(s.file).stem().string();
  }
  return s;
}

}  // namespace

CaseFile read_case_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw bad_input("cannot read case file '" + path + "'");
  json root;
  try {
    root = json::parse(in);
  } catch (const json::parse_error& e) {
    throw bad_input(path + ": not valid JSON: " + e.what());
  }
  const fs::path folder = fs::absolute(fs::path(path)).parent_path();
  CaseFile c;
  c.path = path;
  ObjectReader r(root, "", path);
  c.name = r.string("name", folder.filename().string());

  const json* surfaces = r.find("surfaces");
  if (!surfaces || !surfaces->is_array() || surfaces->empty())
    r.fail("'surfaces' must be a non-empty list (outermost surface first)");
  for (std::size_t i = 0; i < surfaces->size(); ++i)
    c.surfaces.push_back(read_surface_entry((*surfaces)[i], static_cast<int>(i), folder, path));

  const json* materials = r.find("materials");
  if (materials) {
    if (!materials->is_array()) r.fail("'materials' must be a list");
    for (std::size_t i = 0; i < materials->size(); ++i) {
      ObjectReader m((*materials)[i], "materials[" + std::to_string(i) + "]", path);
      CaseMaterial mat;
      mat.name = m.string("name", "material" + std::to_string(i));
      mat.young_modulus = m.required_number("young_modulus");
      mat.poisson_ratio = m.required_number("poisson_ratio");
      m.refuse_unknown();
      if (!(mat.young_modulus > 0.0)) m.fail("'" + m.path("young_modulus") + "' must be positive");
      if (!(mat.poisson_ratio > -1.0 && mat.poisson_ratio < 0.5))
        m.fail("'" + m.path("poisson_ratio") + "' must lie in (-1, 0.5)");
      c.materials.push_back(mat);
    }
    if (c.materials.size() != c.surfaces.size())
      r.fail("'materials' has " + std::to_string(c.materials.size()) + " entries but there are " +
             std::to_string(c.surfaces.size()) + " surfaces (one material inside each surface)");
  } else {
    for (std::size_t i = 0; i < c.surfaces.size(); ++i) c.materials.push_back({"material" + std::to_string(i), 1.0, 0.3});
  }

  c.output_dir = (folder / r.string("output", "output")).lexically_normal().string();

  if (const json* t = r.find("tetmesh")) {
    ObjectReader tr(*t, "tetmesh", path);
    c.tetmesh.radius_edge_ratio = tr.number("radius_edge_ratio", c.tetmesh.radius_edge_ratio);
    c.tetmesh.max_volume = tr.number("max_volume", c.tetmesh.max_volume);
    tr.refuse_unknown();
    if (c.tetmesh.radius_edge_ratio != 0.0 && !(c.tetmesh.radius_edge_ratio > 1.0))
      tr.fail("'tetmesh.radius_edge_ratio' must be 0 (off) or greater than 1.0 (TetGen's refinement needs > 1.0 to end)");
    if (c.tetmesh.max_volume < 0.0) tr.fail("'tetmesh.max_volume' must be 0 (none) or positive");
  }
  if (const json* m = r.find("midsurface")) c.midsurface = parse_midsurface_options(*m, path);
  if (const json* d = r.find("decomposition")) c.volume = parse_decomposition_options(*d, path);
  if (const json* f = r.find("fit")) c.fit = parse_fit_options(*f, path);
  c.midsurface.tetgen = c.tetmesh;
  r.refuse_unknown();
  return c;
}

std::string case_file_json(const CaseFile& c, const std::string& relative_to) {
  json root;
  root["name"] = c.name;
  json surfaces = json::array();
  for (const auto& s : c.surfaces) {
    json e;
    if (s.offset_of) {
      e["offset_of"] = *s.offset_of;
      e["inward"] = s.inward;
    } else {
      e["file"] = fs::path(s.file).lexically_relative(relative_to).string();
    }
    e["label"] = s.label;
    surfaces.push_back(e);
  }
  root["surfaces"] = surfaces;
  json materials = json::array();
  for (const auto& m : c.materials)
    materials.push_back({{"name", m.name}, {"young_modulus", m.young_modulus}, {"poisson_ratio", m.poisson_ratio}});
  root["materials"] = materials;
  root["output"] = fs::path(c.output_dir).lexically_relative(relative_to).string();
  root["tetmesh"] = {{"radius_edge_ratio", c.tetmesh.radius_edge_ratio}, {"max_volume", c.tetmesh.max_volume}};
  return root.dump(2) + "\n";
}

}  // namespace igaprep::cli
