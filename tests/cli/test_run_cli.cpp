// `igaprep run` as a program, on models/sphere2 (the fastest model) with a
// one-patch validation: exit code, one line per stage, the files written,
// report.json's documented keys, report.html, result.h5, the intermediates of
// --keep-intermediate, and a refused case. The method's numbers are checked
// by the pipeline library's tests (tests/pipeline).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "cli/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// sphere2's surfaces and materials, plus `extra` keys (a JSON fragment
// starting with a comma, or empty).
std::string write_case(const std::string& dir, const std::string& extra) {
  const std::string m = models_dir() + "/sphere2/";
  const std::string text = R"({"name": "sphere2-run", "surfaces": [{"file": ")" + m +
                           R"(outer.off", "label": "outer"}, {"file": ")" + m +
                           R"(inner.off", "label": "inner"}], "materials": [{"name": "shell", "young_modulus": 1000, )"
                           R"("poisson_ratio": 0.3}, {"name": "core", "young_modulus": 100, "poisson_ratio": 0.25}])" +
                           extra + "}";
  const std::string path = dir + "/case.json";
  std::ofstream(path) << text;
  return path;
}

// Runs a Python script (the Debian interpreter with h5py and VTK) that
// prints two numbers; false when it does not.
bool python_two_numbers(const std::string& script, double* a, double* b) {
  FILE* pipe = popen((std::string(IGAPREP_PYTHON) + " -c \"" + script + "\"").c_str(), "r");
  if (!pipe) return false;
  const bool ok = fscanf(pipe, "%lf %lf", a, b) == 2;
  pclose(pipe);
  return ok;
}

// Issue 23: headless Chromium renders report.html with the model's picture,
// and none of the run's figure keys shows as text (they are tooltips only).
void expect_report_renders_in_chromium(const std::string& page, const std::string& scratch, const json& figures) {
  std::string command = std::string(IGAPREP_PYTHON) + " " + IGAPREP_SOURCE_DIR + "/tests/cli/report_in_chromium.py " +
                        page + " " + scratch;
  // Keys that are words of their own (min_scaled_jacobian); plain words
  // such as "patches" are prose too.
  for (const auto& [key, value] : figures.items())
    if (key.find('_') != std::string::npos) command += " " + key;
  const CliResult r = run_command(command);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(model_picture (\d+)\nraw_keys (.*)\nscreenshot (\d+) (\d+)\nmodel_pixels (\d+))")))
      << r.out;
  EXPECT_EQ(std::stoi(m[1]), 1) << r.out;
  EXPECT_EQ(m[2], "") << "figure keys shown as text: " << m[2];
  EXPECT_EQ(std::stoi(m[3]), 1280);
  EXPECT_EQ(std::stoi(m[4]), 2400);
  EXPECT_GT(std::stoi(m[5]), 20000) << "the model's picture is not on the screenshot: " << r.out;
}

bool has_type(const json& v, const std::string& type) {
  if (type == "string") return v.is_string();
  if (type == "integer") return v.is_number_integer();
  if (type == "number") return v.is_number();
  if (type == "boolean") return v.is_boolean();
  if (type == "array") return v.is_array();
  if (type == "object") return v.is_object();
  if (type == "object or null") return v.is_object() || v.is_null();
  if (type == "number or null") return v.is_number() || v.is_null();
  ADD_FAILURE() << "unknown documented type " << type;
  return false;
}

// Every key of the pipeline table in docs/check-report.md ("name[]" = every
// element of an array) is present in the run's report with its type.
void check_documented(const json& j, const std::vector<std::string>& seg, std::size_t i, const std::string& key,
                      const std::string& type, int* seen) {
  if (i == seg.size()) {
    ++*seen;
    EXPECT_TRUE(has_type(j, type)) << key << " should be " << type << ", is " << j.dump().substr(0, 80);
    return;
  }
  std::string s = seg[i];
  const bool each = s.size() > 2 && s.substr(s.size() - 2) == "[]";
  if (each) s = s.substr(0, s.size() - 2);
  ASSERT_TRUE(j.is_object() && j.contains(s)) << "report.json lacks documented key pipeline." << key;
  if (!each) return check_documented(j.at(s), seg, i + 1, key, type, seen);
  for (const auto& e : j.at(s)) check_documented(e, seg, i + 1, key, type, seen);
}

void expect_documented_pipeline_keys(const json& p) {
  std::ifstream in(std::string(IGAPREP_SOURCE_DIR) + "/docs/check-report.md");
  const std::regex row(R"(^\| ([a-z_0-9.\[\]]+) \| ([a-z ]+) \|)");
  bool inside = false;
  int rows = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("### The `pipeline` section", 0) == 0) inside = true;
    if (line.rfind("## report.html", 0) == 0) inside = false;
    std::smatch m;
    if (!inside || !std::regex_search(line, m, row)) continue;
    // Only a run with a "tspline" section has these (tests/tspline/tspline_cli_test.cpp checks them).
    if (m[1].str().rfind("figures.tspline_", 0) == 0) continue;
    ++rows;
    std::vector<std::string> seg;
    std::stringstream ss(m[1].str());
    for (std::string s; std::getline(ss, s, '.');) seg.push_back(s);
    int seen = 0;
    check_documented(p, seg, 0, m[1].str(), m[2].str(), &seen);
    EXPECT_GT(seen, 0) << m[1].str();
  }
  EXPECT_GT(rows, 40);
  // The rows with a placeholder (LABEL, I), for sphere2's surfaces.
  for (const char* k : {"fidelity_relative_outer", "fidelity_relative_inner", "volume_difference_region_0",
                        "volume_difference_region_1"})
    EXPECT_TRUE(p.at("figures").contains(k)) << k;
}

// The blocks of the volume parameterization as one conforming tet mesh (its
// faces are the decomposition surfaces) fill the volume of the tet mesh:
// read back with VTK, their signed volume is the tet mesh's within the chords.
void expect_blocks_mesh_fills_the_volume(const std::string& out, double tet_volume) {
  const std::string script =
      "import vtk, numpy as np; from vtk.util.numpy_support import vtk_to_numpy as a; "
      "r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName('" + out + "/decomposition_blocks.vtu'); r.Update(); "
      "g = r.GetOutput(); P = a(g.GetPoints().GetData()); C = a(g.GetCells().GetConnectivityArray()).reshape(-1, 4); "
      "x = [P[C[:, i]] for i in range(4)]; "
      "v = np.einsum('ij,ij->i', np.cross(x[1] - x[0], x[2] - x[0]), x[3] - x[0]) / 6; "
      "print(repr(float(v.sum())), repr(float(np.abs(v).sum())))";
  double signed_volume = 0, abs_volume = 0;
  ASSERT_TRUE(python_two_numbers(script, &signed_volume, &abs_volume));
  EXPECT_NEAR(signed_volume, tet_volume, 0.05 * tet_volume);  // chords of the thinned cells
  EXPECT_LT(abs_volume - signed_volume, 1e-3 * tet_volume) << "inverted tets only where a thinned cell folds";
}

TEST(RunCli, Sphere2EndToEnd) {
  const auto dir = scratch_dir("run_sphere2");
  const std::string out = dir + "/out";
  const auto r = run_cli("run " + write_case(dir, R"(, "export": ["gismo", "mfem", "vtu"],
      "validation": {"patches": 1}, "reduce": {"relative_tolerance": 0.0005},
      "load_case": {"fix": {"label": "outer", "box": [[-2, -2, -2], [-0.3, 2, 2]]},
                    "pressure": {"label": "outer", "value": 1.0, "box": [[0.3, -2, -2], [2, 2, 2]]}})") +
                         " -o " + out + " --keep-intermediate");
  ASSERT_TRUE(fs::exists(out + "/report.json")) << r.out;
  const json report = json::parse(read_all(out + "/report.json"));
  const json p = report.at("pipeline");
  EXPECT_EQ(r.exit_code, p.at("passed").get<bool>() ? 0 : 2) << r.out;
  EXPECT_EQ(p.at("passed").get<bool>(),
            report.at("summary").at("passed").get<bool>() && p.at("validation").at("met").get<bool>());
  // One line per stage, in order.
  std::size_t at = 0;
  for (const char* stage : {"validate ", "midsurface ", "base ", "decompose ", "param ", "fit ", "check_fitted ",
                            "reduce ", "check ", "export ", "validation ", "load_case ", "report "}) {
    const std::size_t next = r.out.find(std::string("\n") + stage, at);
    EXPECT_NE(next, std::string::npos) << stage << "\n" << r.out;
    if (next != std::string::npos) at = next;
  }
  for (const char* f : {"model.h5", "report.json", "report.html", "model.xml", "model.mesh", "model.vtu", "result.h5",
                        "tetmesh.vtu", "midsurface_m0trim.vtu", "base_surface.vtu", "decomposition_w.vtu",
                        "decomposition_samples.vtu", "decomposition_blocks.vtu", "decomposition_blocks_faces.vtu"})
    EXPECT_TRUE(fs::exists(out + "/" + f)) << f << "\n" << r.out;
  EXPECT_FALSE(fs::exists(out + "/model.k"));  // not asked
  EXPECT_NE(read_all(out + "/model.mesh").find("MFEM NURBS mesh"), std::string::npos);
  expect_documented_pipeline_keys(p);
  const std::string html = read_all(out + "/report.html");
  EXPECT_NE(html.find("id=\"pipeline\""), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  // Issue 23, item 3: the run's figures in words (the key as tooltip only),
  // and the files written as links beside the report.
  EXPECT_NE(html.find(">smallest scaled Jacobian<"), std::string::npos);
  EXPECT_EQ(html.find(">max_stitch<"), std::string::npos);
  EXPECT_NE(html.find("<a href=\"model.h5\">"), std::string::npos);
  expect_report_renders_in_chromium(out + "/report.html", dir + "/chromium", p.at("figures"));
  // result.h5's root attributes equal the report's figures.
  double energy = 0, umax = 0;
  ASSERT_TRUE(python_two_numbers("import h5py; f = h5py.File('" + out + "/result.h5', 'r'); "
                                 "print(repr(float(f.attrs['strain_energy'])), repr(float(f.attrs['max_displacement'])))",
                                 &energy, &umax));
  EXPECT_NEAR(energy, p.at("figures").at("load_case_strain_energy").get<double>(), 1e-12 * energy);
  EXPECT_NEAR(umax, p.at("figures").at("load_case_max_displacement").get<double>(), 1e-12 * umax);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(volume ([0-9.]+) \(radius-edge)"))) << r.out;
  expect_blocks_mesh_fills_the_volume(out, std::stod(m[1]));
  // The T-NURCC surfaces of the model just written: one line per surface, three files each.
  // The model was reduced: its knots are not uniform, which the rules here do not cover.
  const auto nonuniform = run_cli("tnurcc " + out + "/model.h5 -o " + dir + "/tnurcc");
  EXPECT_EQ(nonuniform.exit_code, 1) << nonuniform.out;
  EXPECT_NE(nonuniform.out.find("not uniform"), std::string::npos) << nonuniform.out;
  const auto tn = run_cli("tnurcc " + out + "/model.h5 --equal-intervals --iterations 0 -o " + dir + "/tnurcc");
  EXPECT_EQ(tn.exit_code, 0) << tn.out;
  for (const char* label : {"outer", "inner"}) {
    EXPECT_NE(tn.out.find(std::string("tnurcc") + " "), std::string::npos) << tn.out;
    EXPECT_NE(tn.out.find(std::string("'") + label + "': cage of "), std::string::npos) << tn.out;
    for (const char* f : {"_cage.obj", "_intervals.json", "_limit.vtu"})
      EXPECT_TRUE(fs::exists(dir + "/tnurcc/" + label + f)) << label << f << "\n" << tn.out;
  }
  const auto bad = run_cli("tnurcc " + out + "/model.h5 --surface nowhere -o " + dir + "/tnurcc_bad");
  EXPECT_EQ(bad.exit_code, 1) << bad.out;
  EXPECT_NE(bad.out.find("no such label"), std::string::npos) << bad.out;
  EXPECT_FALSE(fs::exists(dir + "/tnurcc_bad"));
}

TEST(RunCli, BadCaseIsRefusedWithExitOneBeforeAnyWork) {
  const auto dir = scratch_dir("run_bad_keys");
  const auto r = run_cli("run " + write_case(dir, R"(, "validation": {"coarse": 1})") + " -o " + dir + "/out");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("error: " + dir + "/case.json: unknown key 'validation.coarse'"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("validate "), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

}  // namespace
