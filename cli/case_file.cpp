#include "case_file.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "case_midsurface.h"
#include "case_volume.h"
#include "igaprep/core/error.h"
#include "igaprep/export/export_model.h"

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
  int integer(const std::string& key, int fallback, int lo, int hi) {
    const json* v = find(key);
    if (!v) return fallback;
    if (!v->is_number_integer()) fail("'" + path(key) + "' must be an integer, got " + v->type_name());
    const long long x = v->get<long long>();
    if (x < lo || x > hi)
      fail("'" + path(key) + "' must lie in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
           std::to_string(x));
    return static_cast<int>(x);
  }
  bool boolean(const std::string& key, bool fallback) {
    const json* v = find(key);
    if (!v) return fallback;
    if (!v->is_boolean()) fail("'" + path(key) + "' must be true or false, got " + v->type_name());
    return v->get<bool>();
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


// "export": a list of format names written beside model.h5.
std::vector<std::string> read_export(const json& v, const std::string& file) {
  if (!v.is_array()) throw bad_input(file + ": 'export' must be a list of format names (gismo, mfem, vtu, bext, hdf5)");
  std::vector<std::string> out;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::string where = "export[" + std::to_string(i) + "]";
    if (!v[i].is_string()) throw bad_input(file + ": '" + where + "' must be a string, got " + v[i].type_name());
    const std::string name = v[i].get<std::string>();
    if (name.find(',') != std::string::npos) throw bad_input(file + ": '" + where + "' must be one format name");
    std::vector<exporter::Format> f;
    try {
      f = exporter::parse_formats(name);
    } catch (const Error& e) {
      throw bad_input(file + ": '" + where + "': " + e.what());
    }
    const std::string canonical = exporter::format_name(f.at(0));
    if (std::find(out.begin(), out.end(), canonical) == out.end()) out.push_back(canonical);
  }
  return out;
}

Eigen::Vector3d read_vector3(const json& v, const std::string& where, const std::string& file) {
  if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
    throw bad_input(file + ": '" + where + "' must be a list of three numbers");
  const Eigen::Vector3d x(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
  if (!x.allFinite()) throw bad_input(file + ": '" + where + "' must be finite");
  return x;
}

// Reads "label" and optional "box" of a load-case entry.
CaseSideSelection read_selection(ObjectReader& r, const std::string& file) {
  CaseSideSelection s;
  s.label = r.string("label", "");
  if (s.label.empty()) r.fail("'" + r.path("label") + "' must name a labelled boundary (a surface label)");
  if (const json* b = r.find("box")) {
    if (!b->is_array() || b->size() != 2)
      r.fail("'" + r.path("box") + "' must be [[xmin, ymin, zmin], [xmax, ymax, zmax]]");
    const Eigen::Vector3d lo = read_vector3((*b)[0], r.path("box") + "[0]", file);
    const Eigen::Vector3d hi = read_vector3((*b)[1], r.path("box") + "[1]", file);
    if (!(lo.array() <= hi.array()).all()) r.fail("'" + r.path("box") + "' must have min <= max in x, y and z");
    s.box = std::array<Eigen::Vector3d, 2>{lo, hi};
  }
  return s;
}

// A single entry or a list of them: calls read(entry, where) for each.
template <class F>
void for_each_entry(const json& v, const std::string& key, F read) {
  if (v.is_array()) {
    for (std::size_t i = 0; i < v.size(); ++i) read(v[i], key + "[" + std::to_string(i) + "]");
  } else {
    read(v, key);
  }
}

CaseLoadCase read_load_case(const json& v, const std::string& file) {
  ObjectReader r(v, "load_case", file);
  CaseLoadCase lc;
  const json* fix = r.find("fix");
  if (!fix) r.fail("missing key 'load_case.fix' (a label, or {\"label\", \"box\", \"components\"}, or a list)");
  for_each_entry(*fix, "load_case.fix", [&](const json& e, const std::string& where) {
    CaseFix f;
    if (e.is_string()) {
      f.where.label = e.get<std::string>();
      if (f.where.label.empty()) throw bad_input(file + ": '" + where + "' must not be empty");
    } else {
      ObjectReader er(e, where, file);
      f.where = read_selection(er, file);
      const std::string comp = er.string("components", "xyz");
      f.components = {{false, false, false}};
      for (char ch : comp) {
        if (ch < 'x' || ch > 'z' || f.components[ch - 'x'])
          er.fail("'" + er.path("components") + "' must be distinct letters of 'xyz', got '" + comp + "'");
        f.components[ch - 'x'] = true;
      }
      if (comp.empty()) er.fail("'" + er.path("components") + "' must not be empty");
      er.refuse_unknown();
    }
    lc.fix.push_back(f);
  });
  if (const json* p = r.find("pressure"))
    for_each_entry(*p, "load_case.pressure", [&](const json& e, const std::string& where) {
      ObjectReader er(e, where, file);
      CasePressure cp;
      cp.where = read_selection(er, file);
      cp.value = er.required_number("value");
      er.refuse_unknown();
      lc.pressure.push_back(cp);
    });
  if (const json* t = r.find("traction"))
    for_each_entry(*t, "load_case.traction", [&](const json& e, const std::string& where) {
      ObjectReader er(e, where, file);
      CaseTraction ct;
      ct.where = read_selection(er, file);
      const json* value = er.find("value");
      if (!value) er.fail("missing key '" + er.path("value") + "' ([tx, ty, tz])");
      ct.value = read_vector3(*value, er.path("value"), file);
      er.refuse_unknown();
      lc.traction.push_back(ct);
    });
  if (const json* b = r.find("body_force")) lc.body_force = read_vector3(*b, "load_case.body_force", file);
  lc.refine = r.integer("refine", lc.refine, 0, 4);
  lc.solver = r.string("solver", lc.solver);
  if (lc.solver != "cg" && lc.solver != "cholesky") r.fail("'load_case.solver' must be \"cg\" or \"cholesky\"");
  r.refuse_unknown();
  return lc;
}

CaseValidation read_validation(const json& v, const std::string& file) {
  ObjectReader r(v, "validation", file);
  CaseValidation c;
  c.enabled = r.boolean("enabled", c.enabled);
  c.coarse_refine = r.integer("coarse_refine", c.coarse_refine, 0, 7);
  c.fine_refine = r.integer("fine_refine", c.fine_refine, 1, 8);
  c.patches = r.integer("patches", c.patches, 0, 1000000);
  c.solver = r.string("solver", c.solver);
  r.refuse_unknown();
  if (c.fine_refine <= c.coarse_refine) r.fail("'validation.fine_refine' must be greater than 'validation.coarse_refine'");
  if (c.solver != "cg" && c.solver != "cholesky") r.fail("'validation.solver' must be \"cg\" or \"cholesky\"");
  return c;
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
  if (const json* f = r.find("fit")) {
    c.fit = parse_fit_options(*f, path);
    c.jacobian = parse_jacobian_options(*f, path);
  }
  if (const json* e = r.find("export")) c.export_formats = read_export(*e, path);
  if (const json* v = r.find("validation")) c.validation = read_validation(*v, path);
  if (const json* l = r.find("load_case")) {
    c.load_case = read_load_case(*l, path);
    // Labels are the surfaces' (whether a side carries it is known after the fit).
    auto known = [&](const CaseSideSelection& w, const std::string& key) {
      std::string list;
      for (const auto& s : c.surfaces) {
        if (s.label == w.label) return;
        list += (list.empty() ? "" : ", ") + s.label;
      }
      r.fail("'" + key + ".label': '" + w.label + "' is not a surface label (labels: " + list + ")");
    };
    for (std::size_t i = 0; i < c.load_case->fix.size(); ++i)
      known(c.load_case->fix[i].where, "load_case.fix[" + std::to_string(i) + "]");
    for (std::size_t i = 0; i < c.load_case->pressure.size(); ++i)
      known(c.load_case->pressure[i].where, "load_case.pressure[" + std::to_string(i) + "]");
    for (std::size_t i = 0; i < c.load_case->traction.size(); ++i)
      known(c.load_case->traction[i].where, "load_case.traction[" + std::to_string(i) + "]");
  }
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
  // Later keys only when they differ from their defaults (the built-in cases stay as they are).
  if (!c.export_formats.empty()) root["export"] = c.export_formats;
  const CaseValidation dv;
  const CaseValidation& v = c.validation;
  if (v.enabled != dv.enabled || v.coarse_refine != dv.coarse_refine || v.fine_refine != dv.fine_refine ||
      v.patches != dv.patches || v.solver != dv.solver)
    root["validation"] = {{"enabled", v.enabled}, {"coarse_refine", v.coarse_refine}, {"fine_refine", v.fine_refine},
                          {"patches", v.patches}, {"solver", v.solver}};
  return root.dump(2) + "\n";
}

}  // namespace igaprep::cli
