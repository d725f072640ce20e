#include "igaprep/pipeline/case.h"

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <limits>
#include <set>

#include "case_sections.h"
#include "json_reader.h"
#include "igaprep/core/error.h"
#include "igaprep/core/input_files.h"
#include "igaprep/export/export_model.h"
#include "igaprep/models/builtin_models.h"

namespace igaprep::pipeline {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// "remesh": "auto", false, or a positive edge length.
void read_remesh(const json& value, const ObjectReader& r, CaseSurface& s) {
  if (value.is_string() && value.get<std::string>() == "auto") {
    s.remesh = CaseSurface::Remesh::Auto;
  } else if (value.is_boolean() && !value.get<bool>()) {
    s.remesh = CaseSurface::Remesh::Off;
  } else if (value.is_number() && value.get<double>() > 0.0) {
    s.remesh = CaseSurface::Remesh::Length;
    s.remesh_length = value.get<double>();
  } else {
    r.fail("'" + r.path("remesh") + "' must be \"auto\", false or a positive edge length, got " + value.dump());
  }
}

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
    if (const json* remesh = r.find("remesh")) read_remesh(*remesh, r, s);
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
    try {
      require_regular_file(resolved.string(), "surface file");
    } catch (const Error& e) {
      throw bad_input(file + ": '" + where + "': " + e.what());
    }
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

iga_check::LinearSolver read_solver(ObjectReader& r, iga_check::LinearSolver fallback) {
  const std::string name = r.string("solver", iga_check::linear_solver_name(fallback));
  try {
    return iga_check::linear_solver_named(name);  // the one list of names
  } catch (const Error&) {
    r.fail("'" + r.path("solver") + "' must be \"auto\", \"cholesky\", \"cg\" or \"amg\"");
  }
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

// Entries {"label", "box", "value": [x, y, z]} (CaseTraction, CaseForce);
// `what` says in an error what the value is.
template <class Load>
void read_vector_loads(const json& v, const std::string& key, const std::string& what, const std::string& file,
                       std::vector<Load>& out) {
  for_each_entry(v, key, [&](const json& e, const std::string& where) {
    ObjectReader er(e, where, file);
    Load load;
    load.where = read_selection(er, file);
    const json* value = er.find("value");
    if (!value) er.fail("missing key '" + er.path("value") + "' (" + what + ")");
    load.value = read_vector3(*value, er.path("value"), file);
    er.refuse_unknown();
    out.push_back(load);
  });
}

// "rotation": {"density", "angular_velocity", "axis" (default z), "point"
// (default the origin)}.
iga_check::RotationLoad read_rotation(const json& v, const std::string& file) {
  ObjectReader r(v, "load_case.rotation", file);
  iga_check::RotationLoad rot;
  rot.density = r.required_number("density");
  if (!(rot.density > 0.0)) r.fail("'load_case.rotation.density' must be positive");
  rot.angular_velocity = r.required_number("angular_velocity");
  if (const json* a = r.find("axis")) rot.axis = read_vector3(*a, "load_case.rotation.axis", file);
  if (!(rot.axis.norm() > 0.0)) r.fail("'load_case.rotation.axis' must not be the zero vector");
  if (const json* p = r.find("point")) rot.point = read_vector3(*p, "load_case.rotation.point", file);
  r.refuse_unknown();
  return rot;
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
  if (const json* t = r.find("traction")) read_vector_loads(*t, "load_case.traction", "[tx, ty, tz]", file, lc.traction);
  if (const json* f = r.find("force"))
    read_vector_loads(*f, "load_case.force", "[Fx, Fy, Fz], the total force", file, lc.force);
  if (const json* b = r.find("body_force")) lc.body_force = read_vector3(*b, "load_case.body_force", file);
  if (const json* rot = r.find("rotation")) lc.rotation = read_rotation(*rot, file);
  lc.refine = r.integer("refine", lc.refine, 0, 4);
  lc.solver = read_solver(r, lc.solver);
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
  c.solver = read_solver(r, c.solver);
  c.finer_when_missed = r.boolean("finer_when_missed", c.finer_when_missed);
  r.refuse_unknown();
  if (c.fine_refine <= c.coarse_refine) r.fail("'validation.fine_refine' must be greater than 'validation.coarse_refine'");
  return c;
}

// Exactly one of the two tolerances, positive.
ReduceSettings read_reduce(const json& v, const std::string& file) {
  ObjectReader r(v, "reduce", file);
  ReduceSettings s;
  const double huge = std::numeric_limits<double>::max();
  s.tolerance = r.number_in("tolerance", 0.0, 0.0, huge);
  s.relative_tolerance = r.number_in("relative_tolerance", 0.0, 0.0, 1.0);
  r.refuse_unknown();
  if ((s.tolerance > 0.0) == (s.relative_tolerance > 0.0))
    r.fail("'reduce' needs exactly one of 'tolerance' (> 0, model units) and 'relative_tolerance' (> 0, a fraction "
           "of the model's diagonal)");
  return s;
}

// Exactly one of the two tolerances, positive; rounds optional.
TSplineSettings read_tspline(const json& v, const std::string& file) {
  ObjectReader r(v, "tspline", file);
  TSplineSettings s;
  s.tolerance = r.number_in("tolerance", 0.0, 0.0, std::numeric_limits<double>::max());
  s.relative_tolerance = r.number_in("relative_tolerance", 0.0, 0.0, 1.0);
  s.rounds = r.integer("rounds", s.rounds, 0, 12);
  r.refuse_unknown();
  if ((s.tolerance > 0.0) == (s.relative_tolerance > 0.0))
    r.fail("'tspline' needs exactly one of 'tolerance' (> 0, model units) and 'relative_tolerance' (> 0, a fraction "
           "of the outer surface's diagonal)");
  return s;
}

// Every key optional; the section's presence asks for the surfaces.
TnurccSettings read_tnurcc(const json& v, const std::string& file) {
  ObjectReader r(v, "tnurcc", file);
  TnurccSettings s;
  s.crease_angle = r.number_in("crease_angle", s.crease_angle, 0.0, 180.0);
  s.fit_iterations = r.integer("fit_iterations", s.fit_iterations, 0, 100);
  s.samples_per_face = r.integer("samples_per_face", s.samples_per_face, 1, 16);
  s.vtu_per_face = r.integer("vtu_per_face", s.vtu_per_face, 1, 32);
  s.equal_intervals = r.boolean("equal_intervals", s.equal_intervals);
  s.smoothing = r.number_in("smoothing", s.smoothing, 0.0, 1e6);
  r.refuse_unknown();
  return s;
}

// Limits in percent in the file, fractions in CheckOptions.
iga_check::CheckOptions read_check(const json& v, const std::string& file) {
  ObjectReader r(v, "check", file);
  iga_check::CheckOptions o;
  o.fidelity_limit = r.number_in("fidelity_limit", 100.0 * o.fidelity_limit, 1e-6, 100.0) / 100.0;
  o.volume_limit = r.number_in("volume_limit", 100.0 * o.volume_limit, 1e-6, 100.0) / 100.0;
  r.refuse_unknown();
  return o;
}

std::vector<CaseMaterial> read_materials(ObjectReader& r, std::size_t surfaces, const std::string& file) {
  std::vector<CaseMaterial> out;
  const json* materials = r.find("materials");
  if (!materials) {
    for (std::size_t i = 0; i < surfaces; ++i) out.push_back({"material" + std::to_string(i), 1.0, 0.3});
    return out;
  }
  if (!materials->is_array()) r.fail("'materials' must be a list");
  for (std::size_t i = 0; i < materials->size(); ++i) {
    ObjectReader m((*materials)[i], "materials[" + std::to_string(i) + "]", file);
    CaseMaterial mat;
    mat.name = m.string("name", "material" + std::to_string(i));
    mat.young_modulus = m.required_number("young_modulus");
    mat.poisson_ratio = m.required_number("poisson_ratio");
    m.refuse_unknown();
    if (!(mat.young_modulus > 0.0)) m.fail("'" + m.path("young_modulus") + "' must be positive");
    if (!(mat.poisson_ratio > -1.0 && mat.poisson_ratio < 0.5))
      m.fail("'" + m.path("poisson_ratio") + "' must lie in (-1, 0.5)");
    out.push_back(mat);
  }
  if (out.size() != surfaces)
    r.fail("'materials' has " + std::to_string(out.size()) + " entries but there are " + std::to_string(surfaces) +
           " surfaces (one material inside each surface)");
  return out;
}

mesh::TetgenOptions read_tetmesh(const json& t, const std::string& file) {
  ObjectReader tr(t, "tetmesh", file);
  mesh::TetgenOptions o;
  o.radius_edge_ratio = tr.number("radius_edge_ratio", o.radius_edge_ratio);
  o.max_volume = tr.number("max_volume", o.max_volume);
  o.max_tets = tr.number("max_tets", o.max_tets);
  tr.refuse_unknown();
  if (o.radius_edge_ratio != 0.0 && !(o.radius_edge_ratio > 1.0))
    tr.fail("'tetmesh.radius_edge_ratio' must be 0 (off) or greater than 1.0 (TetGen's refinement needs > 1.0 to end)");
  if (o.max_volume < 0.0) tr.fail("'tetmesh.max_volume' must be 0 (none) or positive");
  if (!(o.max_tets >= 1.0)) tr.fail("'tetmesh.max_tets' must be at least 1");
  return o;
}

// Labels are the surfaces' (whether a side carries one is known after the fit).
void check_load_case_labels(const Case& c, const ObjectReader& r) {
  auto known = [&](const CaseSideSelection& w, const std::string& key) {
    std::string list;
    for (const auto& s : c.surfaces) {
      if (s.label == w.label) return;
      list += (list.empty() ? "" : ", ") + s.label;
    }
    r.fail("'" + key + ".label': '" + w.label + "' is not a surface label (labels: " + list + ")");
  };
  const CaseLoadCase& lc = *c.load_case;
  for (std::size_t i = 0; i < lc.fix.size(); ++i) known(lc.fix[i].where, "load_case.fix[" + std::to_string(i) + "]");
  for (std::size_t i = 0; i < lc.pressure.size(); ++i)
    known(lc.pressure[i].where, "load_case.pressure[" + std::to_string(i) + "]");
  for (std::size_t i = 0; i < lc.traction.size(); ++i)
    known(lc.traction[i].where, "load_case.traction[" + std::to_string(i) + "]");
}

// nlohmann keeps the last of repeated keys without a word (two "surfaces"
// would give a one-surface model): refuse them, naming the key. Its own
// errors (syntax, a number such as 1e400 that overflows) become bad input.
json parse_json_refusing_repeated_keys(const std::string& text, const std::string& source) {
  std::vector<std::set<std::string>> keys;  // of each object being read
  const json::parser_callback_t refuse_repeated = [&](int, json::parse_event_t event, json& parsed) {
    if (event == json::parse_event_t::object_start) keys.emplace_back();
    if (event == json::parse_event_t::object_end) keys.pop_back();
    if (event == json::parse_event_t::key && !keys.back().insert(parsed.get<std::string>()).second)
      throw bad_input(source + ": key '" + parsed.get<std::string>() +
                      "' appears twice in one object (JSON keeps only the last; remove one)");
    return true;
  };
  try {
    return json::parse(text, refuse_repeated);
  } catch (const json::exception& e) {
    std::string what = e.what();
    const std::size_t cut = what.find("] ");  // "[json.exception.parse_error.101] ..."
    throw bad_input(source + ": not valid JSON: " + (cut == std::string::npos ? what : what.substr(cut + 2)));
  }
}

// Labels name the boundary groups of the model (load cases, exports).
void refuse_repeated_labels(const std::vector<CaseSurface>& surfaces, const ObjectReader& r) {
  for (std::size_t i = 0; i < surfaces.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (surfaces[i].label == surfaces[j].label)
        r.fail("'surfaces[" + std::to_string(i) + "]' has the label '" + surfaces[i].label + "' of 'surfaces[" +
               std::to_string(j) + "]': each surface needs its own label");
}

// The stage sections, each optional.
void read_sections(ObjectReader& r, const std::string& file, Case& c) {
  if (const json* t = r.find("tetmesh")) c.tetmesh = read_tetmesh(*t, file);
  if (const json* m = r.find("midsurface")) c.midsurface = read_midsurface_section(*m, file);
  if (const json* d = r.find("decomposition")) read_decomposition_section(*d, file, c.base, c.volume, c.auto_spread_deviation, c.cover_rounds);
  if (const json* f = r.find("fit")) read_fit_section(*f, file, c.fit, c.fit_retry, c.surface_fit, c.jacobian);
  if (const json* e = r.find("export")) c.export_formats = read_export(*e, file);
  if (const json* k = r.find("check")) c.check = read_check(*k, file);
  if (const json* v = r.find("validation")) c.validation = read_validation(*v, file);
  if (const json* d = r.find("reduce")) c.reduce = read_reduce(*d, file);
  if (const json* d = r.find("tnurcc")) c.tnurcc = read_tnurcc(*d, file);
  if (const json* d = r.find("tspline")) c.tspline = read_tspline(*d, file);
  if (c.tspline && c.fit.degree % 2 == 0)
    r.fail("'tspline' needs an odd 'fit.degree' (the local refinement keeps even degrees analysis-suitable only "
           "with rules not built yet; docs/tspline.md)");
  // Refused now rather than after the run's work: a reduced model's knots
  // are not uniform, which only equal intervals cover so far.
  if (c.reduce && c.tnurcc && !c.tnurcc->equal_intervals)
    r.fail("'tnurcc' after 'reduce' needs \"equal_intervals\": true (the reduced model's knots are not uniform, "
           "and the limit surface of unequal knot intervals is not evaluated yet; docs/tnurcc.md)");
  if (const json* l = r.find("load_case")) {
    c.load_case = read_load_case(*l, file);
    check_load_case_labels(c, r);
  }
  c.midsurface.tetgen = c.tetmesh;
}

}  // namespace

Case parse_case(const std::string& json_text, const std::string& folder_name, const std::string& source) {
  const json root = parse_json_refusing_repeated_keys(json_text, source);
  const fs::path folder = fs::absolute(fs::path(folder_name.empty() ? "." : folder_name)).lexically_normal();
  Case c;
  c.text = json_text;
  ObjectReader r(root, "", source);
  r.find("comment");  // free text for people (where a case's choices came from); not read
  c.name = r.string("name", folder.filename().string());
  const json* surfaces = r.find("surfaces");
  if (!surfaces || !surfaces->is_array() || surfaces->empty())
    r.fail("'surfaces' must be a non-empty list (outermost surface first)");
  for (std::size_t i = 0; i < surfaces->size(); ++i)
    c.surfaces.push_back(read_surface_entry((*surfaces)[i], static_cast<int>(i), folder, source));
  refuse_repeated_labels(c.surfaces, r);
  c.materials = read_materials(r, c.surfaces.size(), source);
  c.output_dir = (folder / r.string("output", "output")).lexically_normal().string();
  read_sections(r, source, c);
  // w0 lies between Tn and M: known only with the number of surfaces.
  const double innermost = static_cast<double>(c.surfaces.size() - 1) / static_cast<double>(c.surfaces.size());
  if (c.volume.w0 >= 0.0 && !(c.volume.w0 > innermost && c.volume.w0 < 1.0))
    r.fail("'decomposition.w0' must lie in (" + std::to_string(innermost) + ", 1) with " +
           std::to_string(c.surfaces.size()) + " surface(s) (T(n+1) between Tn and M), got " + std::to_string(c.volume.w0));
  r.refuse_unknown();
  return c;
}

Case read_case(const std::string& path) {
  Case c = parse_case(read_input_file(path, "case file"), fs::absolute(fs::path(path)).parent_path().string(), path);
  c.path = path;
  return c;
}

Case builtin_case(const std::string& name) {
  models::BuiltinModel model = models::make_builtin_model(name);
  Case c;
  c.name = model.name;
  for (std::size_t i = 0; i < model.surfaces.size(); ++i) {
    CaseSurface s;
    s.label = model.labels[i];
    s.mesh = std::move(model.surfaces[i]);
    c.surfaces.push_back(std::move(s));
    const auto& m = model.materials[i];
    c.materials.push_back({m.name, m.young_modulus, m.poisson_ratio});
  }
  c.output_dir = (fs::current_path() / "output").string();
  c.midsurface.tetgen = c.tetmesh;
  return c;
}

}  // namespace igaprep::pipeline
