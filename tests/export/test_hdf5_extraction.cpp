// The Bezier-extraction model file: h5py and an independent evaluator
// written from docs/hdf5-format.md reproduce the multipatch's geometry.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "igaprep/core/error.h"
#include "igaprep/export/export_model.h"
#include "igaprep/export/hdf5_extraction.h"
#include "igaprep/export/hdf5_model.h"
#include "igaprep/export/vtu_bezier.h"
#include "igaprep/spline/evaluate.h"
#include "igaprep/spline/extraction_model.h"
#include "test_model.h"
#include "test_util.h"

namespace {
using namespace igaprep::test;
namespace spline = igaprep::spline;

TEST(Hdf5Extraction, AnIndependentReaderReproducesTheGeometry) {
  const std::string dir = scratch_dir("hdf5_extraction");
  const spline::MultiPatch mp = make_test_model();
  const spline::ExtractionModel m = spline::extraction_model(mp);
  igaprep::exporter::write_hdf5_extraction(m, dir + "/m.h5");
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<std::array<double, 4>> at;
  std::ostringstream points;
  points << "[";
  for (std::size_t e = 0; e < m.elements.size(); ++e)
    for (int s = 0; s < 10; ++s) {
      at.push_back({static_cast<double>(e), unit(rng), unit(rng), unit(rng)});
      points << (at.size() > 1 ? "," : "") << "[" << e << "," << at.back()[1] << "," << at.back()[2] << ","
             << at.back()[3] << "]";
    }
  points << "]";
  const CommandResult r = run_python("eval_extraction.py", {dir + "/m.h5", points.str()});
  ASSERT_EQ(r.status, 0) << r.output.substr(0, 2000);
  const nlohmann::json j = nlohmann::json::parse(r.output);
  EXPECT_EQ(j["format"], "igaprep-bezier-extraction");
  EXPECT_EQ(j["format_version"], 1);
  EXPECT_EQ(j["functions"].get<int>(), m.function_count());
  EXPECT_EQ(j["elements"].get<std::size_t>(), m.elements.size());
  EXPECT_EQ(j["faces"].get<std::size_t>(), m.boundary_faces.size());
  EXPECT_EQ(j["labels"].get<std::vector<std::string>>(), mp.labels);
  EXPECT_EQ(j["materials"].size(), mp.materials.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < at.size(); ++i) {
    // The printed t has 6 digits: evaluate ours at the same rounded t.
    const spline::ExtractionElement& el = m.elements[static_cast<std::size_t>(at[i][0])];
    Eigen::Vector3d xi;
    for (int d = 0; d < 3; ++d) {
      std::ostringstream s;
      s << at[i][static_cast<std::size_t>(d) + 1];
      xi[d] = el.domain[d][0] + std::stod(s.str()) * (el.domain[d][1] - el.domain[d][0]);
    }
    const Eigen::Vector3d x = spline::evaluate_point(mp.patches[static_cast<std::size_t>(el.patch)], xi);
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(j["points"][i][c].get<double>() - x[c]));
  }
  EXPECT_LT(worst, 1e-12 * 3.0);  // the slab's diagonal is 3
  std::filesystem::remove_all(dir);
}

TEST(Hdf5Extraction, AnInconsistentModelIsRefusedAndNothingWritten) {
  const std::string dir = scratch_dir("hdf5_extraction_bad");
  spline::ExtractionModel m = spline::extraction_model(make_test_model());
  m.elements[2].functions.back() = m.function_count();
  EXPECT_THROW(igaprep::exporter::write_hdf5_extraction(m, dir + "/bad.h5"), igaprep::Error);
  EXPECT_FALSE(std::filesystem::exists(dir + "/bad.h5"));
  std::filesystem::remove_all(dir);
}

TEST(Hdf5Extraction, ReadBackEqualsWhatWasWritten) {
  const std::string dir = scratch_dir("hdf5_extraction_read");
  const spline::ExtractionModel m = spline::extraction_model(make_test_model());
  igaprep::exporter::write_hdf5_extraction(m, dir + "/m.h5");
  const spline::ExtractionModel r = igaprep::exporter::read_hdf5_extraction(dir + "/m.h5");
  EXPECT_EQ(r.control_points, m.control_points);
  EXPECT_EQ(r.weights, m.weights);
  ASSERT_EQ(r.operators.size(), m.operators.size());
  for (std::size_t k = 0; k < m.operators.size(); ++k) EXPECT_EQ(r.operators[k], m.operators[k]);
  ASSERT_EQ(r.elements.size(), m.elements.size());
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    EXPECT_EQ(r.elements[e].degrees, m.elements[e].degrees);
    EXPECT_EQ(r.elements[e].functions, m.elements[e].functions);
    EXPECT_EQ(r.elements[e].extraction, m.elements[e].extraction);
    EXPECT_EQ(r.elements[e].material, m.elements[e].material);
    EXPECT_EQ(r.elements[e].patch, m.elements[e].patch);
    EXPECT_EQ(r.elements[e].index, m.elements[e].index);
    EXPECT_EQ(r.elements[e].domain, m.elements[e].domain);
  }
  ASSERT_EQ(r.boundary_faces.size(), m.boundary_faces.size());
  for (std::size_t f = 0; f < m.boundary_faces.size(); ++f) {
    EXPECT_EQ(r.boundary_faces[f].element, m.boundary_faces[f].element);
    EXPECT_EQ(r.boundary_faces[f].side, m.boundary_faces[f].side);
    EXPECT_EQ(r.boundary_faces[f].label, m.boundary_faces[f].label);
  }
  EXPECT_EQ(r.labels, m.labels);
  ASSERT_EQ(r.materials.size(), m.materials.size());
  EXPECT_EQ(r.materials[1].young_modulus, m.materials[1].young_modulus);
  EXPECT_EQ(r.provenance_generator, m.provenance_generator);
  // A damaged file is refused naming the dataset (changed in place by h5py).
  for (const auto& [change, dataset] : std::vector<std::pair<std::string, std::string>>{
           {"f['elements/functions'][0] = 10**6", "/elements/functions"},
           {"f['elements/function_offsets'][1] = -1", "/elements/function_offsets"},
           {"f['elements/extraction'][0] = 999", "/elements/extraction"},
           {"f['operators/shape'][0, 0] = 7", "/operators/shape"},
           {"f['weights'][0] = 0.0", "/weights"},
           {"f['boundary_faces'][0, 1] = 9", "/boundary_faces"}}) {
    igaprep::exporter::write_hdf5_extraction(m, dir + "/bad.h5");
    const CommandResult py = run_command(std::string(IGAPREP_PYTHON) + " -c \"import h5py; f = h5py.File('" + dir +
                                         "/bad.h5', 'r+'); " + change + "\"");
    ASSERT_EQ(py.status, 0) << change;
    try {
      igaprep::exporter::read_hdf5_extraction(dir + "/bad.h5");
      ADD_FAILURE() << change << ": no error";
    } catch (const igaprep::Error& e) {
      EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput) << e.what();
      EXPECT_NE(std::string(e.what()).find(dataset), std::string::npos) << change << ": " << e.what();
    }
  }
  std::filesystem::remove_all(dir);
}

// The extraction model as VTU (issue 18): VTK reads the same points and
// cells as from the multipatch's VTU; `export` writes it from the file.
TEST(Hdf5Extraction, ItsVtuHasTheMultipatchsCellsAndPoints) {
  const std::string dir = scratch_dir("extraction_vtu");
  spline::MultiPatch mp = make_test_model();
  for (auto& p : mp.patches) p.displacement.resize(0, 0);
  mp.has_solution = false;
  igaprep::exporter::write_vtu_bezier(mp, dir + "/m.vtu");
  igaprep::exporter::write_hdf5_extraction(spline::extraction_model(mp), dir + "/t.h5");
  const CommandResult r = run_command(std::string(IGAPREP_CLI) + " export " + dir + "/t.h5 --to vtu -o " + dir + "/t 2>&1");
  ASSERT_EQ(r.status, 0) << r.output;
  // Formats of tensor-product patches are refused; BEXT is written (read
  // back in tests/tspline/tspline_cli_test.cpp), as many elements as the
  // multipatch's part by part.
  const CommandResult bad = run_command(std::string(IGAPREP_CLI) + " export " + dir + "/t.h5 --to gismo -o " + dir + "/t 2>&1");
  EXPECT_EQ(WEXITSTATUS(bad.status), 1) << bad.output;
  EXPECT_NE(bad.output.find("written as vtu or bext, not gismo"), std::string::npos) << bad.output;
  const CommandResult bext = run_command(std::string(IGAPREP_CLI) + " export " + dir + "/t.h5 --to bext -o " + dir + "/t 2>&1");
  ASSERT_EQ(bext.status, 0) << bext.output;
  igaprep::exporter::export_model(mp, dir + "/m", {igaprep::exporter::Format::Bext});
  for (const std::string part : {"_part1.bext", "_part2.bext"}) {
    const CommandResult a = run_python("read_bext.py", {dir + "/m" + part}), b = run_python("read_bext.py", {dir + "/t" + part});
    ASSERT_EQ(a.status, 0) << a.output.substr(0, 1000);
    ASSERT_EQ(b.status, 0) << b.output.substr(0, 1000);
    EXPECT_EQ(nlohmann::json::parse(a.output)["elements"].size(), nlohmann::json::parse(b.output)["elements"].size()) << part;
    EXPECT_EQ(nlohmann::json::parse(a.output)["nodes"], nlohmann::json::parse(b.output)["nodes"]) << part;
  }
  const std::string script =
      "import vtk, numpy as np\n"
      "from vtk.util.numpy_support import vtk_to_numpy\n"
      "def read(f):\n"
      "  r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName(f); r.Update(); g = r.GetOutput()\n"
      "  return g.GetNumberOfCells(), np.array(sorted(map(tuple, np.round(vtk_to_numpy(g.GetPoints().GetData()), 9))))\n"
      "a, pa = read('" + dir + "/m.vtu'); b, pb = read('" + dir + "/t.vtu')\n"
      "print(a, b, len(pa), len(pb), np.abs(pa - pb).max() if len(pa) == len(pb) else -1)\n";
  std::ofstream(dir + "/cmp.py") << script;
  const CommandResult py = run_command(std::string(IGAPREP_PYTHON) + " " + dir + "/cmp.py");
  ASSERT_EQ(py.status, 0) << py.output;
  std::istringstream in(py.output);
  long cells_m = 0, cells_t = 0, points_m = 0, points_t = 0;
  double gap = -1;
  in >> cells_m >> cells_t >> points_m >> points_t >> gap;
  EXPECT_EQ(cells_t, cells_m);
  EXPECT_GT(cells_m, 0);
  EXPECT_EQ(points_t, points_m);
  EXPECT_GE(gap, 0.0);
  EXPECT_LT(gap, 1e-8);
  std::filesystem::remove_all(dir);
}

// `igaprep tspline MODEL.h5 -o OUT.h5`: the model's extraction form on disk,
// the counts on stdout; an output that is the input is refused.
TEST(Hdf5Extraction, TheTsplineCommandConvertsAModelFile) {
  const std::string dir = scratch_dir("tspline_cli");
  const spline::MultiPatch mp = make_test_model();
  igaprep::exporter::write_hdf5_model(mp, dir + "/m.h5");
  const spline::ExtractionModel m = spline::extraction_model(mp);
  const CommandResult r = run_command(std::string(IGAPREP_CLI) + " tspline " + dir + "/m.h5 -o " + dir + "/t.h5");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("tspline: " + std::to_string(m.function_count()) + " functions, " +
                          std::to_string(m.elements.size()) + " elements"),
            std::string::npos)
      << r.output;
  const CommandResult read = run_python("eval_extraction.py", {dir + "/t.h5", "[[0, 0.5, 0.5, 0.5]]"});
  ASSERT_EQ(read.status, 0) << read.output;
  const nlohmann::json j = nlohmann::json::parse(read.output);
  EXPECT_EQ(j["functions"].get<int>(), m.function_count());
  const Eigen::Vector3d x = spline::evaluate_element(m, 0, Eigen::Vector3d(0.5, 0.5, 0.5));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(j["points"][0][c].get<double>(), x[c], 1e-12);
  const CommandResult same = run_command(std::string(IGAPREP_CLI) + " tspline " + dir + "/m.h5 -o " + dir + "/m.h5 2>&1");
  EXPECT_EQ(WEXITSTATUS(same.status), 1) << same.output;
  EXPECT_NE(same.output.find("error: "), std::string::npos) << same.output;
  std::filesystem::remove_all(dir);
}

}  // namespace
