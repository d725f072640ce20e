// `igaprep run` end to end on models/sphere2 (the fastest model): outputs,
// the report's pipeline section, export formats, the load case, exit codes,
// and the case keys "export", "validation" and "load_case" refused by name.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <unistd.h>

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

std::string scratch_dir(const std::string& name) {
  const fs::path dir = fs::path(IGAPREP_BINARY_DIR) / "tests" / "cli_scratch" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

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

// One run shared by the assertions below: exports, a one-patch validation
// (about 2 s) and a load case fixing the sides of the outer surface whose
// centre has x < -0.3, with a pressure on those with x > 0.3. ctest runs each
// test in its own process: the run is kept on disk with a stamp (the
// executable's time and the case text) and reused while the stamp matches;
// a lock keeps parallel test processes from running it twice.
class RunSphere2 : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const fs::path dir = fs::path(IGAPREP_BINARY_DIR) / "tests" / "cli_scratch" / "run_sphere2";
    fs::create_directories(dir);
    dir_ = new std::string(dir.string());
    const int lock = open((dir / "lock").c_str(), O_CREAT | O_RDWR, 0644);
    if (lock >= 0) flock(lock, LOCK_EX);
    const std::string c = write_case(*dir_, R"(, "export": ["gismo", "mfem", "vtu"],
      "validation": {"patches": 1, "coarse_refine": 0, "fine_refine": 1},
      "load_case": {"fix": {"label": "outer", "box": [[-2, -2, -2], [-0.3, 2, 2]]},
                    "pressure": {"label": "outer", "value": 1.0, "box": [[0.3, -2, -2], [2, 2, 2]]}})");
    const std::string stamp =
        std::to_string(fs::last_write_time(IGAPREP_CLI).time_since_epoch().count()) + "\n" + read_all(c);
    result_ = new CliResult;
    if (read_all(*dir_ + "/stamp") == stamp && fs::exists(*dir_ + "/run.log")) {
      std::istringstream log(read_all(*dir_ + "/run.log"));
      log >> result_->exit_code;
      result_->out.assign(std::istreambuf_iterator<char>(log), {});
    } else {
      fs::remove(*dir_ + "/stamp");
      fs::remove_all(*dir_ + "/out");
      *result_ = run_cli("run " + c + " -o " + *dir_ + "/out");
      std::ofstream(*dir_ + "/run.log") << result_->exit_code << result_->out;
      std::ofstream(*dir_ + "/stamp") << stamp;
    }
    if (lock >= 0) close(lock);  // releases the lock
  }
  static void TearDownTestSuite() {
    delete dir_;
    delete result_;
  }
  static std::string out(const std::string& name) { return *dir_ + "/out/" + name; }
  static json report() { return json::parse(read_all(out("report.json"))); }

  static std::string* dir_;
  static CliResult* result_;
};
std::string* RunSphere2::dir_ = nullptr;
CliResult* RunSphere2::result_ = nullptr;

// Runs a Python script (the Debian interpreter with h5py and VTK) that
// prints two numbers; false when it does not.
bool python_two_numbers(const std::string& script, double* a, double* b) {
  FILE* pipe = popen((std::string(IGAPREP_PYTHON) + " -c \"" + script + "\"").c_str(), "r");
  if (!pipe) return false;
  const bool ok = fscanf(pipe, "%lf %lf", a, b) == 2;
  pclose(pipe);
  return ok;
}

TEST_F(RunSphere2, ExitCodeFollowsTheVerdict) {
  ASSERT_TRUE(fs::exists(out("report.json"))) << result_->out;
  const json p = report().at("pipeline");
  const bool check_passed = report().at("summary").at("passed").get<bool>();
  const bool met = p.at("validation").at("met").get<bool>();
  EXPECT_EQ(p.at("passed").get<bool>(), check_passed && met);
  EXPECT_EQ(result_->exit_code, check_passed && met ? 0 : 2) << result_->out;
}

TEST_F(RunSphere2, PrintsOneLinePerStage) {
  for (const char* stage : {"validate ", "tetmesh ", "midsurface ", "decompose ", "param ", "fit ", "check ",
                            "export ", "validation ", "load case ", "report "})
    EXPECT_NE(result_->out.find(std::string("\n") + stage), std::string::npos) << stage << "\n" << result_->out;
  // Stage order: check, export, validation, load case.
  EXPECT_LT(result_->out.find("\ncheck "), result_->out.find("\nexport "));
  EXPECT_LT(result_->out.find("\nexport "), result_->out.find("\nvalidation "));
  EXPECT_LT(result_->out.find("\nvalidation "), result_->out.find("\nload case "));
}

TEST_F(RunSphere2, WritesModelReportAndAskedFormats) {
  for (const char* f : {"model.h5", "report.json", "report.html", "model.xml", "model.mesh", "model.vtu", "result.h5"})
    EXPECT_TRUE(fs::exists(out(f))) << f << "\n" << result_->out;
  EXPECT_FALSE(fs::exists(out("model.bext")));  // not asked
  EXPECT_NE(read_all(out("model.xml")).find("<xml"), std::string::npos);
  EXPECT_NE(read_all(out("model.mesh")).find("MFEM NURBS mesh"), std::string::npos);
  const json outputs = report().at("pipeline").at("outputs");
  for (const char* f : {"model.h5", "model.xml", "model.mesh", "model.vtu", "result.h5", "report.json"})
    EXPECT_NE(std::find(outputs.begin(), outputs.end(), json(f)), outputs.end()) << f;
}

TEST_F(RunSphere2, PipelineSectionHasStagesAndFigures) {
  const json r = report();
  const json p = r.at("pipeline");
  EXPECT_EQ(p.at("case").get<std::string>(), "sphere2-run");
  std::vector<std::string> names;
  double total = 0.0;
  for (const auto& s : p.at("stages")) {
    names.push_back(s.at("name").get<std::string>());
    EXPECT_GE(s.at("seconds").get<double>(), 0.0);
    total += s.at("seconds").get<double>();
  }
  const std::vector<std::string> expected = {"validate", "tetmesh", "midsurface", "decompose", "param", "fit", "check",
                                             "export", "validation", "load_case"};
  EXPECT_EQ(names, expected);
  EXPECT_NEAR(p.at("total_seconds").get<double>(), total, 1e-9 * (1 + total));
  const json f = p.at("figures");
  // The figures agree with the check report's own counts.
  EXPECT_EQ(f.at("patches").get<long>(), r.at("summary").at("patches").get<long>());
  EXPECT_EQ(f.at("elements").get<long>(), r.at("summary").at("elements").get<long>());
  EXPECT_EQ(f.at("negative_elements").get<long>(), r.at("summary").at("negative").get<long>());
  EXPECT_GT(f.at("patches").get<long>(), 1);
  EXPECT_GT(f.at("interfaces").get<long>(), 0);
  EXPECT_TRUE(f.at("interfaces").is_number_integer());
  EXPECT_EQ(f.at("degree").get<int>(), 3);
  EXPECT_EQ(f.at("elements").get<long>(),
            f.at("patches").get<long>() * static_cast<long>(std::pow(f.at("elements_per_direction").get<int>(), 3)));
  EXPECT_GT(f.at("load_case_strain_energy").get<double>(), 0.0);
  EXPECT_GT(f.at("load_case_max_displacement").get<double>(), 0.0);
}

TEST_F(RunSphere2, ValidationRateIsMeasured) {
  const json v = report().at("pipeline").at("validation");
  ASSERT_TRUE(v.at("ran").get<bool>()) << v.dump(2);
  EXPECT_EQ(v.at("patches").get<int>(), 1);
  EXPECT_EQ(v.at("degree").get<int>(), 3);
  EXPECT_DOUBLE_EQ(v.at("required_rate").get<double>(), 3.5);
  ASSERT_EQ(v.at("levels").size(), 2u);
  const json c = v.at("levels")[0], f = v.at("levels")[1];
  EXPECT_EQ(c.at("refine").get<int>(), 0);
  EXPECT_EQ(f.at("refine").get<int>(), 1);
  EXPECT_EQ(f.at("elements").get<long>(), 8 * c.at("elements").get<long>());
  EXPECT_NEAR(c.at("h").get<double>() / f.at("h").get<double>(), 2.0, 1e-9);
  // The rate is what the two errors say, and a degree-3 model converges near p + 1.
  const double rate = std::log(c.at("l2_error").get<double>() / f.at("l2_error").get<double>()) / std::log(2.0);
  EXPECT_NEAR(v.at("l2_rate").get<double>(), rate, 1e-6);
  EXPECT_GT(rate, 3.0);
  EXPECT_LT(rate, 6.0);
  EXPECT_LT(f.at("l2_relative").get<double>(), 1e-3);
  EXPECT_EQ(v.at("met").get<bool>(), rate >= 3.5);
}

TEST_F(RunSphere2, LoadCaseResultCarriesItsFigures) {
  // result.h5's root attributes equal the report's figures.
  const std::string script = "import h5py; f = h5py.File('" + out("result.h5") +
                             "', 'r'); print(repr(float(f.attrs['strain_energy'])), "
                             "repr(float(f.attrs['max_displacement'])))";
  double energy = 0, umax = 0;
  ASSERT_TRUE(python_two_numbers(script, &energy, &umax));
  const json f = report().at("pipeline").at("figures");
  EXPECT_NEAR(energy, f.at("load_case_strain_energy").get<double>(), 1e-12 * energy);
  EXPECT_NEAR(umax, f.at("load_case_max_displacement").get<double>(), 1e-12 * umax);
}

bool has_type(const json& v, const std::string& type) {
  if (type == "string") return v.is_string();
  if (type == "integer") return v.is_number_integer();
  if (type == "number") return v.is_number();
  if (type == "boolean") return v.is_boolean();
  if (type == "array") return v.is_array();
  if (type == "object") return v.is_object();
  if (type == "object or null") return v.is_object() || v.is_null();
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

TEST_F(RunSphere2, DocumentedPipelineKeysArePresent) {
  std::ifstream in(std::string(IGAPREP_SOURCE_DIR) + "/docs/check-report.md");
  const std::regex row(R"(^\| ([a-z_0-9.\[\]]+) \| ([a-z ]+) \|)");
  const json p = report().at("pipeline");
  bool inside = false;
  int rows = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("### The `pipeline` section", 0) == 0) inside = true;
    if (line.rfind("## report.html", 0) == 0) inside = false;
    std::smatch m;
    if (!inside || !std::regex_search(line, m, row)) continue;
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

TEST_F(RunSphere2, HtmlShowsThePipeline) {
  const std::string html = read_all(out("report.html"));
  EXPECT_NE(html.find("id=\"pipeline\""), std::string::npos);
  EXPECT_NE(html.find("Manufactured-solution validation"), std::string::npos);
  EXPECT_NE(html.find("decompose"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
}

struct Refused {
  const char* extra;
  const char* message;
};

TEST(RunCli, BadCaseKeysAreRefusedByName) {
  const auto dir = scratch_dir("run_bad_keys");
  const Refused cases[] = {
      {R"(, "export": ["gismo", "stl"])", "'export[1]': unknown export format 'stl'"},
      {R"(, "export": "gismo")", "'export' must be a list"},
      {R"(, "validation": {"coarse": 1})", "unknown key 'validation.coarse'"},
      {R"(, "validation": {"coarse_refine": 2, "fine_refine": 1})", "'validation.fine_refine' must be greater"},
      {R"(, "validation": {"patches": -1})", "'validation.patches' must lie in"},
      {R"(, "validation": {"solver": "lu"})", "'validation.solver'"},
      {R"(, "validation": {"enabled": 1})", "'validation.enabled' must be true or false"},
      {R"(, "load_case": {"pressure": {"label": "outer", "value": 1}})", "missing key 'load_case.fix'"},
      {R"(, "load_case": {"fix": "outer", "pressure": {"label": "outer"}})", "missing key 'load_case.pressure.value'"},
      {R"(, "load_case": {"fix": {"label": "outer", "components": "xw"}})", "'load_case.fix.components'"},
      {R"(, "load_case": {"fix": [{"label": "outer", "box": [[1, 0, 0], [0, 1, 1]]}]})", "'load_case.fix[0].box'"},
      {R"(, "load_case": {"fix": "outer", "traction": {"label": "top", "value": [0, 0, 1]}})",
       "'load_case.traction[0].label': 'top' is not a surface label (labels: outer, inner)"},
  };
  for (const auto& c : cases) {
    const auto r = run_cli("run " + write_case(dir, c.extra) + " -o " + dir + "/out");
    EXPECT_EQ(r.exit_code, 1) << c.extra << "\n" << r.out;
    EXPECT_NE(r.out.find(c.message), std::string::npos) << c.extra << "\n" << r.out;
    EXPECT_FALSE(fs::exists(dir + "/out/model.h5")) << c.extra;  // refused before any work
  }
}

TEST(RunCli, LoadCaseBoxWithoutSidesIsNamedAndValidationCanBeOff) {
  const auto dir = scratch_dir("run_empty_box");
  const auto r = run_cli("run " +
                         write_case(dir, R"(, "validation": {"enabled": false},
                           "load_case": {"fix": {"label": "outer", "box": [[5, 5, 5], [6, 6, 6]]}})") +
                         " -o " + dir + "/out");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("'load_case.fix[0].box': none of the"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("validation    off"), std::string::npos) << r.out;
  // The model was made: it and the report of what ran are kept.
  ASSERT_TRUE(fs::exists(dir + "/out/model.h5"));
  const json p = json::parse(read_all(dir + "/out/report.json")).at("pipeline");
  EXPECT_TRUE(p.at("validation").is_null());
  EXPECT_EQ(p.at("verdict").get<std::string>().rfind("ERROR: load case", 0), 0u) << p.dump(2);
  EXPECT_FALSE(fs::exists(dir + "/out/result.h5"));
}

}  // namespace

namespace {

// --keep-intermediate writes the intermediate meshes, among them the blocks
// of the volume parameterization as one conforming tet mesh (its faces are
// the decomposition surfaces): no open and no non-manifold face, 6 tets per
// (thinned) sample cell, and it fills the volume of the tet mesh.
TEST(RunCli, KeepIntermediateWritesTheBlocksAsOneTetMesh) {
  const auto dir = scratch_dir("run_keep_intermediate");
  const auto r = run_cli("run " + write_case(dir, R"(, "validation": {"enabled": false})") + " -o " + dir +
                         "/out --keep-intermediate");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  for (const char* f : {"tetmesh.vtu", "midsurface_m0trim.vtu", "decomposition_base.vtu", "decomposition_w.vtu",
                        "decomposition_samples.vtu", "decomposition_blocks.vtu", "decomposition_blocks_faces.vtu"})
    EXPECT_TRUE(fs::exists(dir + "/out/" + f)) << f;
  std::smatch m;
  const std::string& o = r.out;
  ASSERT_TRUE(std::regex_search(o, m, std::regex(R"(\((\d+) cells per block direction\): (\d+) tets, \d+ merged points, \d+ non-positive, (\d+) open faces, (\d+) non-manifold)")))
      << o;
  const int cells = std::stoi(m[1]);
  EXPECT_EQ(std::stol(m[2]), 26L * cells * cells * cells * 6) << "sphere2: 26 blocks";
  EXPECT_EQ(std::stoi(m[3]), 0);
  EXPECT_EQ(std::stoi(m[4]), 0);
  ASSERT_TRUE(std::regex_search(o, m, std::regex(R"(volume ([0-9.]+) \(radius-edge)"))) << o;
  const double tet_volume = std::stod(m[1]);
  // Signed and absolute volume of the blocks' tets (read back with VTK).
  const std::string script =
      "import vtk, numpy as np; from vtk.util.numpy_support import vtk_to_numpy as a; "
      "r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName('" + dir + "/out/decomposition_blocks.vtu'); r.Update(); "
      "g = r.GetOutput(); P = a(g.GetPoints().GetData()); C = a(g.GetCells().GetConnectivityArray()).reshape(-1, 4); "
      "x = [P[C[:, i]] for i in range(4)]; "
      "v = np.einsum('ij,ij->i', np.cross(x[1] - x[0], x[2] - x[0]), x[3] - x[0]) / 6; "
      "print(repr(float(v.sum())), repr(float(np.abs(v).sum())))";
  double signed_volume = 0, abs_volume = 0;
  ASSERT_TRUE(python_two_numbers(script, &signed_volume, &abs_volume));
  // Chords of 8 cells per block side cut about 3 % off sphere2's volume.
  EXPECT_NEAR(signed_volume, tet_volume, 0.05 * tet_volume);
  EXPECT_LT(abs_volume - signed_volume, 1e-3 * tet_volume) << "inverted tets only where a thinned cell folds";
}

}  // namespace
