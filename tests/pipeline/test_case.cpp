// Case files through the library: every bad key refused with bad_input
// naming the key, before any work; the built-in cases; case_json.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "igaprep/core/error.h"
#include "igaprep/models/builtin_models.h"
#include "igaprep/pipeline/case.h"
#include "pipeline_runs.h"

namespace {

using igaprep::pipeline::Case;
using igaprep::pipeline::parse_case;
using pipeline_test::models_dir;

// sphere2's two surfaces and materials, plus `extra` keys (text starting with a comma, or empty).
std::string sphere2_case(const std::string& extra) {
  const std::string m = models_dir() + "/sphere2/";
  return R"({"name": "sphere2-case", "surfaces": [{"file": ")" + m + R"(outer.off", "label": "outer"}, {"file": ")" +
         m + R"(inner.off", "label": "inner"}], "materials": [{"name": "shell", "young_modulus": 1000, )"
             R"("poisson_ratio": 0.3}, {"name": "core", "young_modulus": 100, "poisson_ratio": 0.25}])" +
         extra + "}";
}

// The message of the bad_input that parsing `text` throws ("" if none).
std::string refusal(const std::string& text) {
  try {
    parse_case(text, models_dir() + "/sphere2", "case.json");
  } catch (const igaprep::Error& e) {
    EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput) << e.what();
    return e.what();
  }
  return "";
}

struct Refused {
  const char* extra;
  const char* message;
};

TEST(Case, BadKeysAreRefusedByName) {
  const Refused cases[] = {
      {R"(, "tetmesh": {"radius_edge": 2})", "case.json: unknown key 'tetmesh.radius_edge'"},
      {R"(, "tetmesh": {"max_volume": "big"})", "'tetmesh.max_volume' must be a number"},
      {R"(, "tetmesh": {"radius_edge_ratio": 1.0})", "greater than 1.0"},
      {R"(, "export": ["gismo", "stl"])", "'export[1]': unknown export format 'stl'"},
      {R"(, "export": "gismo")", "'export' must be a list"},
      {R"(, "validation": {"coarse": 1})", "unknown key 'validation.coarse'"},
      {R"(, "validation": {"coarse_refine": 2, "fine_refine": 1})", "'validation.fine_refine' must be greater"},
      {R"(, "validation": {"patches": -1})", "'validation.patches' must lie in"},
      {R"(, "validation": {"solver": "lu"})", "'validation.solver' must be \"auto\", \"cholesky\", \"cg\" or \"amg\""},
      {R"(, "load_case": {"fix": "outer", "solver": "hypre"})", "'load_case.solver' must be \"auto\""},
      {R"(, "validation": {"enabled": 1})", "'validation.enabled' must be true or false"},
      {R"(, "load_case": {"pressure": {"label": "outer", "value": 1}})", "missing key 'load_case.fix'"},
      {R"(, "load_case": {"fix": "outer", "pressure": {"label": "outer"}})", "missing key 'load_case.pressure.value'"},
      {R"(, "load_case": {"fix": {"label": "outer", "components": "xw"}})", "'load_case.fix.components'"},
      {R"(, "load_case": {"fix": [{"label": "outer", "box": [[1, 0, 0], [0, 1, 1]]}]})", "'load_case.fix[0].box'"},
      {R"(, "load_case": {"fix": "outer", "traction": {"label": "top", "value": [0, 0, 1]}})",
       "'load_case.traction[0].label': 'top' is not a surface label (labels: outer, inner)"},
      {R"(, "load_case": {"fix": "outer", "force": {"label": "outer"}})", "missing key 'load_case.force.value'"},
      {R"(, "load_case": {"fix": "outer", "rotation": {"density": 2.7e-9}})",
       "missing key 'load_case.rotation.angular_velocity'"},
      {R"(, "load_case": {"fix": "outer", "rotation": {"density": 0, "angular_velocity": 1}})",
       "'load_case.rotation.density' must be positive"},
      {R"(, "load_case": {"fix": "outer", "rotation": {"density": 1, "angular_velocity": 1, "axis": [0, 0, 0]}})",
       "'load_case.rotation.axis' must not be the zero vector"},
      {R"(, "load_case": {"fix": "outer", "rotation": {"density": 1, "angular_velocity": 1, "speed": 2}})",
       "unknown key 'load_case.rotation.speed'"},
      {R"(, "midsurface": {"colour": 1})", "unknown key 'midsurface.colour'"},
      {R"(, "midsurface": {"m0": 0.4})", "'midsurface.m0' is no longer read"},
      {R"(, "midsurface": {"cut": "planar"})", "'midsurface.cut' must be"},
      {R"(, "midsurface": {"cut": {"plane": {"point": [0, 0, 0]}}})", "needs 'point' and 'normal'"},
      {R"(, "decomposition": {"colour": 1})", "decomposition.colour"},
      {R"(, "decomposition": {"strategy": 3})", "'decomposition.strategy' must lie in [1, 2]"},
      {R"(, "decomposition": {"strategy": 1.5})", "'decomposition.strategy' must be an integer"},
      {R"(, "decomposition": {"theta": 2.0})", "'decomposition.theta' must be a number in"},
      {R"(, "decomposition": {"inset": 1.0})", "decomposition.inset"},
      {R"(, "decomposition": {"smoothing": -1})", "decomposition.smoothing"},
      {R"(, "decomposition": {"surface_degree": 2.5})", "decomposition.surface_degree"},
      {R"(, "decomposition": {"surface_degree": 13})", "decomposition.surface_degree"},
      {R"(, "decomposition": {"corner_share": 0.6})", "'decomposition.corner_share' must be a number in"},
      {R"(, "decomposition": {"lid_relax_rings": 65})", "decomposition.lid_relax_rings"},
      {R"(, "decomposition": {"sliding_uv": "yes"})", "'decomposition.sliding_uv' must be true or false"},
      {R"(, "decomposition": {"max_aspect": 0.5})", "'decomposition.max_aspect' must be 0 (no cuts) or at least 1"},
      {R"(, "decomposition": {"max_aspect": -1})", "decomposition.max_aspect"},
      {R"(, "decomposition": {"rim_reach": 0.5})", "'decomposition.rim_reach' must be 0 (no cap) or at least 1"},
      {R"(, "decomposition": {"rim_reach": -1})", "decomposition.rim_reach"},
      {R"(, "decomposition": {"w0": 1})", "'decomposition.w0' must lie in (0.500000, 1) with 2 surface(s)"},
      {R"(, "decomposition": {"w0": 0.4})", "'decomposition.w0' must lie in (0.500000, 1) with 2 surface(s)"},
      {R"(, "decomposition": {"spread_deviation": "always"})",
       "'decomposition.spread_deviation' must be \"auto\" or a number in [0, 0.1], got \"always\""},
      {R"(, "decomposition": {"spread_deviation": 0.2})", "decomposition.spread_deviation"},
      {R"(, "fit": {"elements": 0})", "fit.elements"},
      {R"(, "fit": {"degree": 2.5})", "fit.degree"},
      {R"(, "fit": {"knots": 3})", "unknown key 'fit.knots'"},
      {R"(, "fit": {"jacobian_target": 0.95})", "fit.jacobian_target"},
      {R"(, "fit": {"jacobian_sweeps": 2.5})", "fit.jacobian_sweeps"},
      {R"(, "fit": {"jacobian_iterations": -1})", "fit.jacobian_iterations"},
      {R"(, "fit": {"jacobian_points": 1})", "fit.jacobian_points"},
      {R"(, "fit": {"surface_iterations": -1})", "fit.surface_iterations"},
      {R"(, "fit": {"surface_smoothing": -0.1})", "fit.surface_smoothing"},
      {R"(, "tnurcc": {"crease_angle": 200})", "'tnurcc.crease_angle' must be a number in"},
      {R"(, "tnurcc": {"fit": true})", "unknown key 'tnurcc.fit'"},
      {R"(, "reduce": {"tolerance": 0.01}, "tnurcc": {})", "'tnurcc' after 'reduce' needs \"equal_intervals\": true"},
      {R"(, "tspline": {})", "'tspline' needs exactly one of 'tolerance'"},
      {R"(, "tspline": {"tolerance": 0.01, "relative_tolerance": 0.001})", "'tspline' needs exactly one of 'tolerance'"},
      {R"(, "tspline": {"relative_tolerance": 2})", "'tspline.relative_tolerance' must be a number in"},
      {R"(, "tspline": {"tolerance": 0.01, "rounds": 13})", "'tspline.rounds' must lie in [0, 12]"},
      {R"(, "tspline": {"tolerance": 0.01}, "fit": {"degree": 2})", "'tspline' needs an odd 'fit.degree'"},
      {R"(, "colour": 1)", "unknown key 'colour'"},
  };
  for (const auto& c : cases) {
    const std::string message = refusal(sphere2_case(c.extra));
    EXPECT_NE(message.find(c.message), std::string::npos) << c.extra << "\n" << message;
  }
}

TEST(Case, SurfacesAndMaterialsAreChecked) {
  EXPECT_NE(refusal(R"({"surfaces": ["nowhere.stl"]})").find("'surfaces[0]' names a file that does not exist"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"surfaces": []})").find("'surfaces' must be a non-empty list"), std::string::npos);
  const std::string one = R"({"surfaces": ["outer.off"], "materials": [)";
  const std::string mat = R"({"name": "a", "young_modulus": 1, "poisson_ratio": 0.3})";
  EXPECT_NE(refusal(one + mat + ", " + mat + "]}").find("'materials' has 2 entries but there are 1 surfaces"),
            std::string::npos);
  EXPECT_NE(refusal(one + R"({"young_modulus": 1, "poisson_ratio": 0.5}]})").find("materials[0].poisson_ratio"),
            std::string::npos);
  EXPECT_NE(refusal("{not json").find("case.json: not valid JSON"), std::string::npos);
}

// Issue 21, items 9, 10 and 11: what JSON and the file system allow but a
// case must not be.
TEST(Case, RepeatedKeysLabelsHugeNumbersAndNonRegularFilesAreRefused) {
  // Two "surfaces" keys: JSON keeps the last without a word.
  EXPECT_NE(refusal(R"({"surfaces": ["a.off"], "surfaces": ["outer.off"]})")
                .find("case.json: key 'surfaces' appears twice in one object"),
            std::string::npos);
  EXPECT_NE(refusal(sphere2_case(R"(, "fit": {"elements": 3, "elements": 4})")).find("key 'elements' appears twice"),
            std::string::npos);
  // The same key in two objects is fine.
  EXPECT_EQ(refusal(sphere2_case(R"(, "validation": {"enabled": false}, "check": {"fidelity_limit": 1})")), "");
  // Two surfaces with one label.
  const std::string m = models_dir() + "/sphere2/";
  EXPECT_NE(refusal(R"({"surfaces": [{"file": ")" + m + R"(outer.off", "label": "skin"}, {"file": ")" + m +
                    R"(inner.off", "label": "skin"}]})")
                .find("'surfaces[1]' has the label 'skin' of 'surfaces[0]': each surface needs its own label"),
            std::string::npos);
  // A number that overflows a double is bad input naming the file.
  EXPECT_NE(refusal(sphere2_case(R"(, "tetmesh": {"max_volume": 1e400})")).find("case.json: not valid JSON: "),
            std::string::npos);
  // A folder, a FIFO or a device as the case file or a surface.
  const std::string dir = pipeline_test::scratch_dir("case_files");
  try {
    igaprep::pipeline::read_case(dir);
    ADD_FAILURE() << "a folder read as a case";
  } catch (const igaprep::Error& e) {
    EXPECT_NE(std::string(e.what()).find(": is a folder, not a case file"), std::string::npos) << e.what();
  }
  EXPECT_NE(refusal(R"({"surfaces": ["/dev/null"]})").find("/dev/null: is not a regular file"), std::string::npos)
      << refusal(R"({"surfaces": ["/dev/null"]})");
}

TEST(Case, ValuesAreReadAndPathsResolved) {
  const Case c = parse_case(sphere2_case(R"(, "output": "out", "decomposition": {"inset": 0.4, "strategy": 1, "max_aspect": 3, "rim_reach": 3},
      "fit": {"elements": 4, "jacobian_target": 0, "surface_iterations": 3, "surface_smoothing": 0.5}, "midsurface": {"cut": {"plane": {"point": [0, 0, 0.1],
      "normal": [0, 0, 2]}}}, "validation": {"solver": "cg", "patches": 0}, "load_case": {"fix": "outer", "solver": "amg"})"),
                            models_dir() + "/sphere2", "case.json");
  EXPECT_EQ(c.name, "sphere2-case");
  EXPECT_EQ(c.output_dir, models_dir() + "/sphere2/out");
  EXPECT_EQ(c.surfaces.at(1).file, models_dir() + "/sphere2/inner.off");
  EXPECT_EQ(c.base.inset, 0.4);
  EXPECT_EQ(c.base.smoothing, 5);  // the one default for M's smoothing
  EXPECT_EQ(c.base.max_aspect, 3.0);
  EXPECT_EQ(c.base.rim_reach, 3.0);
  EXPECT_EQ(c.volume.strategy, 1);
  EXPECT_TRUE(c.auto_spread_deviation);  // absent: "auto"
  EXPECT_EQ(c.volume.spread_deviation, 0.0);
  EXPECT_EQ(c.fit.elements, 4);
  EXPECT_EQ(c.jacobian.target, 0.0);
  EXPECT_EQ(c.surface_fit.iterations, 3);
  EXPECT_EQ(c.surface_fit.smoothing, 0.5);
  EXPECT_EQ(c.midsurface.cut, igaprep::param::MidsurfaceOptions::CutKind::Plane);
  EXPECT_EQ(c.midsurface.plane.normal.z(), 2.0);
  EXPECT_EQ(c.validation.solver, igaprep::iga_check::LinearSolver::ConjugateGradient);
  EXPECT_EQ(c.validation.patches, 0);
  EXPECT_EQ(c.load_case->solver, igaprep::iga_check::LinearSolver::Amg);
  EXPECT_EQ(c.materials.at(1).young_modulus, 100.0);
  const Case given = parse_case(sphere2_case(R"(, "decomposition": {"spread_deviation": 0.002})"),
                                models_dir() + "/sphere2", "case.json");
  EXPECT_FALSE(given.auto_spread_deviation);
  EXPECT_EQ(given.volume.spread_deviation, 0.002);
  const Case named = parse_case(sphere2_case(R"(, "decomposition": {"spread_deviation": "auto"})"),
                                models_dir() + "/sphere2", "case.json");
  EXPECT_TRUE(named.auto_spread_deviation);
  // Defaults: the study and the load case choose by size.
  const Case d = parse_case(sphere2_case(R"(, "load_case": {"fix": "outer"})"), models_dir() + "/sphere2", "case.json");
  EXPECT_EQ(d.validation.solver, igaprep::iga_check::LinearSolver::Automatic);
  EXPECT_EQ(d.load_case->solver, igaprep::iga_check::LinearSolver::Automatic);
}

// The built-in case made in memory is the committed case: same surfaces
// (bit for bit), labels, materials and options.
TEST(Case, BuiltinCaseEqualsTheCommittedOne) {
  for (const std::string name : igaprep::models::builtin_model_names()) {
    const Case b = igaprep::pipeline::builtin_case(name);
    const Case f = igaprep::pipeline::read_case(models_dir() + "/" + name + "/case.json");
    ASSERT_EQ(b.surfaces.size(), f.surfaces.size()) << name;
    EXPECT_EQ(b.name, f.name);
    for (std::size_t i = 0; i < b.surfaces.size(); ++i) {
      EXPECT_EQ(b.surfaces[i].label, f.surfaces[i].label);
      ASSERT_TRUE(b.surfaces[i].mesh.has_value());
      EXPECT_TRUE(b.surfaces[i].file.empty());
      EXPECT_EQ(b.materials[i].name, f.materials[i].name);
      EXPECT_EQ(b.materials[i].young_modulus, f.materials[i].young_modulus);
      EXPECT_EQ(b.materials[i].poisson_ratio, f.materials[i].poisson_ratio);
    }
    // Options: everything after the surfaces is the same text.
    auto options = [](const Case& c) {
      nlohmann::json j = nlohmann::json::parse(igaprep::pipeline::case_json(c, "", true));
      j.erase("surfaces");
      j.erase("output");
      return j.dump();
    };
    EXPECT_EQ(options(b), options(f)) << name;
  }
  EXPECT_THROW(igaprep::pipeline::builtin_case("cube"), igaprep::Error);
}

// case_json with every option reads back to the same options.
TEST(Case, AllOptionsJsonReadsBack) {
  const Case c = parse_case(sphere2_case(R"(, "decomposition": {"inset": 0.4, "theta": 0.9, "rim_reach": 0, "corner_share": 0.15, "lid_relax_rings": 4}, "export": ["vtu"],
      "tspline": {"relative_tolerance": 0.002, "rounds": 2},
      "load_case": {"fix": {"label": "outer", "components": "xz"}, "traction": {"label": "inner", "value": [0, 1, 0]},
                    "force": {"label": "outer", "box": [[0, 0, 0], [2, 2, 2]], "value": [0, 0, -2000]},
                    "rotation": {"density": 2.7e-9, "angular_velocity": 1000, "axis": [0, 1, 0], "point": [1, 0, 0]}})"),
                            models_dir() + "/sphere2", "case.json");
  const std::string text = igaprep::pipeline::case_json(c, models_dir() + "/sphere2", true);
  const Case back = parse_case(text, models_dir() + "/sphere2", "back.json");
  EXPECT_EQ(igaprep::pipeline::case_json(back, models_dir() + "/sphere2", true), text);
  EXPECT_EQ(back.volume.theta, 0.9);
  EXPECT_EQ(back.base.rim_reach, 0.0);
  EXPECT_EQ(back.volume.corner_share, 0.15);
  EXPECT_EQ(back.volume.lid_relax_rings, 4);
  EXPECT_TRUE(back.auto_spread_deviation);
  const Case given = parse_case(sphere2_case(R"(, "decomposition": {"spread_deviation": 0.003})"),
                                models_dir() + "/sphere2", "case.json");
  const Case given_back =
      parse_case(igaprep::pipeline::case_json(given, models_dir() + "/sphere2", true), models_dir() + "/sphere2", "back.json");
  EXPECT_FALSE(given_back.auto_spread_deviation);
  EXPECT_EQ(given_back.volume.spread_deviation, 0.003);
  ASSERT_TRUE(back.tspline);
  EXPECT_EQ(back.tspline->relative_tolerance, 0.002);
  EXPECT_EQ(back.tspline->rounds, 2);
  ASSERT_TRUE(back.load_case);
  EXPECT_FALSE(back.load_case->fix.at(0).components[1]);
  EXPECT_EQ(back.load_case->traction.at(0).value.y(), 1.0);
  EXPECT_EQ(back.load_case->force.at(0).value.z(), -2000.0);
  EXPECT_EQ((*back.load_case->force.at(0).where.box)[1].x(), 2.0);
  ASSERT_TRUE(back.load_case->rotation);
  EXPECT_EQ(back.load_case->rotation->density, 2.7e-9);
  EXPECT_EQ(back.load_case->rotation->angular_velocity, 1000.0);
  EXPECT_EQ(back.load_case->rotation->axis, Eigen::Vector3d(0, 1, 0));
  EXPECT_EQ(back.load_case->rotation->point, Eigen::Vector3d(1, 0, 0));
}

}  // namespace

namespace {

// sphere2's outer surface alone with `remesh` set to the JSON text given.
std::string remesh_case(const std::string& remesh) {
  return R"({"surfaces": [{"file": ")" + models_dir() + R"(/sphere2/outer.off", "remesh": )" + remesh + "}]}";
}

TEST(Case, RemeshIsAutoOffOrALength) {
  using Remesh = igaprep::pipeline::CaseSurface::Remesh;
  const std::string folder = models_dir() + "/sphere2";
  EXPECT_EQ(parse_case(remesh_case("\"auto\""), folder, "c.json").surfaces[0].remesh, Remesh::Auto);
  EXPECT_EQ(parse_case(remesh_case("false"), folder, "c.json").surfaces[0].remesh, Remesh::Off);
  const Case c = parse_case(remesh_case("0.25"), folder, "c.json");
  EXPECT_EQ(c.surfaces[0].remesh, Remesh::Length);
  EXPECT_DOUBLE_EQ(c.surfaces[0].remesh_length, 0.25);
  // Written back by case_json and read again.
  const Case back = parse_case(igaprep::pipeline::case_json(c, "", true), folder, "back.json");
  EXPECT_EQ(back.surfaces[0].remesh, Remesh::Length);
  EXPECT_DOUBLE_EQ(back.surfaces[0].remesh_length, 0.25);
  for (const char* bad : {"true", "0", "-1", "\"often\""})
    EXPECT_NE(refusal(remesh_case(bad)).find("'surfaces[0].remesh' must be \"auto\", false or a positive edge length"),
              std::string::npos)
        << bad;
}

}  // namespace

namespace {

TEST(Case, WaypointLoopsAreReadAndWrittenBack) {
  const std::string folder = models_dir() + "/sphere2";
  const Case c = parse_case(
      sphere2_case(R"(, "midsurface": {"cut": {"waypoints": [[[1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0]]]}})"),
      folder, "c.json");
  ASSERT_EQ(c.midsurface.cut, igaprep::param::MidsurfaceOptions::CutKind::Waypoints);
  ASSERT_EQ(c.midsurface.waypoints.size(), 1u);
  ASSERT_EQ(c.midsurface.waypoints[0].size(), 4u);
  EXPECT_DOUBLE_EQ(c.midsurface.waypoints[0][3].y(), -1.0);
  const Case back = parse_case(igaprep::pipeline::case_json(c, "", true), folder, "back.json");
  ASSERT_EQ(back.midsurface.waypoints.size(), 1u);
  EXPECT_DOUBLE_EQ(back.midsurface.waypoints[0][1].y(), 1.0);
  EXPECT_NE(refusal(sphere2_case(R"(, "midsurface": {"cut": {"waypoints": [[[1, 0, 0], [0, 1, 0]]]}})"))
                .find("'midsurface.cut.waypoints[0]' must be a list of at least 3 points"),
            std::string::npos);
  EXPECT_NE(refusal(sphere2_case(R"(, "midsurface": {"cut": {"waypoints": [], "loops": []}})"))
                .find("needs exactly one of 'plane', 'loops' and 'waypoints'"),
            std::string::npos);
}

}  // namespace

namespace {

// The case fuzzer's inputs replayed (scripts/fuzz.sh): the seed corpus and
// every input it once crashed on (fuzz/regressions/case/), each parsed or
// refused as bad input.
TEST(FuzzInputs, EveryCaseInputIsParsedOrRefusedAsBadInput) {
  namespace fs = std::filesystem;
  const fs::path fuzz = fs::path(IGAPREP_SOURCE_DIR) / "fuzz";
  int replayed = 0;
  for (const char* folder : {"corpus/case", "regressions/case"}) {
    if (!fs::is_directory(fuzz / folder)) continue;
    for (const auto& entry : fs::directory_iterator(fuzz / folder)) {
      std::ifstream in(entry.path(), std::ios::binary);
      const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      try {
        parse_case(text, "/nonexistent-fuzz-folder", "fuzz.json");
      } catch (const igaprep::Error& e) {
        EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput) << entry.path() << ": " << e.what();
      }
      ++replayed;
    }
  }
  EXPECT_GE(replayed, 5);  // the committed seeds
}

}  // namespace
