// G+Smo XML and MFEM NURBS mesh, each parsed back by an independent Python
// reader (tests/export/read_gismo.py, read_mfem.py) and compared with the model.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "igaprep/core/error.h"
#include "igaprep/export/gismo_xml.h"
#include "igaprep/export/mfem_mesh.h"
#include "igaprep/spline/curve_surface.h"
#include "test_model.h"
#include "test_util.h"

namespace {
using igaprep::spline::MultiPatch;
using json = nlohmann::json;
using namespace igaprep::test;

json run_reader(const std::string& script, const std::string& file) {
  const CommandResult r = run_python(script, {file});
  EXPECT_EQ(r.status, 0) << r.output;
  return json::parse(r.output);
}

TEST(GismoXml, IndependentReaderGetsTheModelBack) {
  const std::string dir = scratch_dir("gismo");
  const MultiPatch mp = make_test_model();
  igaprep::exporter::write_gismo_xml(mp, dir + "/m.xml");
  const json g = run_reader("read_gismo.py", dir + "/m.xml");

  ASSERT_EQ(g["patches"].size(), mp.patches.size());
  for (size_t i = 0; i < mp.patches.size(); ++i) {
    const auto& p = mp.patches[i];
    const json& q = g["patches"][i];
    SCOPED_TRACE("patch " + std::to_string(i));
    EXPECT_EQ(q["type"], p.rational() ? "TensorNurbs3" : "TensorBSpline3");
    for (int d = 0; d < 3; ++d) {
      EXPECT_EQ(q["degrees"][d].get<int>(), p.degrees[d]);
      EXPECT_EQ(q["knots"][d].get<std::vector<double>>(), p.knots[d]);  // exact
    }
    ASSERT_EQ(q["coefs"].size(), static_cast<size_t>(p.control_points.rows()));
    for (Eigen::Index r = 0; r < p.control_points.rows(); ++r)
      for (int c = 0; c < 3; ++c) ASSERT_EQ(q["coefs"][r][c].get<double>(), p.control_points(r, c));
    const std::vector<double> w = q["weights"].get<std::vector<double>>();
    ASSERT_EQ(static_cast<Eigen::Index>(w.size()), p.weights.size());
    for (size_t k = 0; k < w.size(); ++k) EXPECT_EQ(w[k], p.weights[k]);
  }
  // Interfaces (normal-direction entries as G+Smo computes them; the test
  // model stores them that way) and their surface names.
  ASSERT_EQ(g["interfaces"].size(), mp.interfaces.size());
  std::set<std::vector<std::string>> expected, got;
  auto row = [](const json& r) {
    std::vector<std::string> v;
    for (const auto& x : r) v.push_back(x.is_string() ? x.get<std::string>() : std::to_string(x.get<int>()));
    return v;
  };
  for (const auto& f : mp.interfaces) {
    json r = {f.patch_a,   f.side_a.index(), f.patch_b, f.side_b.index(), f.dirmap[0], f.dirmap[1],
              f.dirmap[2], f.orient[0], f.orient[1], f.orient[2], f.surface >= 0 ? mp.labels[f.surface] : ""};
    expected.insert(row(r));
  }
  for (const auto& r : g["interfaces"]) got.insert(row(r));
  EXPECT_EQ(got, expected);
  // Boundaries with their label names.
  std::set<std::vector<std::string>> eb, gb;
  for (const auto& b : mp.boundaries) eb.insert(row(json{b.patch, b.side.index(), mp.labels[b.label]}));
  for (const auto& r : g["boundaries"]) gb.insert(row(r));
  EXPECT_EQ(gb, eb);
  EXPECT_EQ(gb.size(), 16u);
  EXPECT_EQ(g.contains("displacement"), mp.has_solution);
  std::filesystem::remove_all(dir);
}

// Issue 23, item 4: materials as gsOptionLists, a boundary-condition
// template naming every labelled group, and a solve result's displacement
// as a second multipatch on the same bases (it was silently dropped).
TEST(GismoXml, MaterialsBoundaryConditionsAndTheDisplacementAreWritten) {
  const std::string dir = scratch_dir("gismo_bc");
  MultiPatch mp = make_test_model();
  for (std::size_t i = 0; i < mp.patches.size(); ++i) {
    auto& p = mp.patches[i];
    p.displacement = p.control_points * 1e-3 + Eigen::MatrixXd::Constant(p.control_points.rows(), 3, 0.1 * i);
  }
  mp.has_solution = true;
  mp.strain_energy = 2.5;
  igaprep::exporter::write_gismo_xml(mp, dir + "/m.xml");
  const json g = run_reader("read_gismo.py", dir + "/m.xml");

  std::set<std::string> labels;
  for (const auto& b : mp.boundaries) labels.insert(mp.labels[b.label]);
  std::set<std::string> named;
  for (const auto& c : g["conditions"]) {
    EXPECT_EQ(c[0], "Neumann");
    EXPECT_EQ(c[1], 0);
    EXPECT_EQ(c[2], 0);
    named.insert(c[3].get<std::string>());
  }
  EXPECT_EQ(named, labels);
  EXPECT_EQ(g["functions"]["0"], json({"0", "0", "0"}));

  ASSERT_EQ(g["materials"].size(), mp.materials.size());
  std::vector<int> material_of(mp.patches.size(), -1);
  for (std::size_t m = 0; m < mp.materials.size(); ++m) {
    const json& o = g["materials"][m];
    EXPECT_EQ(o["Material"], mp.materials[m].name);
    EXPECT_EQ(o["YoungsModulus"].get<double>(), mp.materials[m].young_modulus);
    EXPECT_EQ(o["PoissonsRatio"].get<double>(), mp.materials[m].poisson_ratio);
    std::istringstream ids(o["Patches"].get<std::string>());
    for (int i; ids >> i;) material_of[static_cast<std::size_t>(i)] = static_cast<int>(m);
  }
  for (std::size_t i = 0; i < mp.patches.size(); ++i) EXPECT_EQ(material_of[i], mp.patches[i].material) << "patch " << i;

  ASSERT_EQ(g["displacement"].size(), mp.patches.size());
  for (std::size_t i = 0; i < mp.patches.size(); ++i) {
    const Eigen::MatrixXd& u = mp.patches[i].displacement;
    ASSERT_EQ(g["displacement"][i].size(), static_cast<std::size_t>(u.rows()));
    for (Eigen::Index r = 0; r < u.rows(); ++r)
      for (int c = 0; c < 3; ++c) ASSERT_EQ(g["displacement"][i][r][c].get<double>(), u(r, c));  // exact
  }
  std::filesystem::remove_all(dir);
}

TEST(MfemMesh, IndependentReaderGetsTheModelBackAndMfemChecksPass) {
  const std::string dir = scratch_dir("mfem");
  const MultiPatch mp = make_test_model();
  igaprep::exporter::write_mfem_mesh(mp, dir + "/m.mesh");
  const json m = run_reader("read_mfem.py", dir + "/m.mesh");

  EXPECT_TRUE(m["problems"].empty()) << m["problems"].dump(1);
  // 2 x 2 x 1 patches: 3 x 3 x 2 vertices, 33 edges, 5 knot-vector classes
  // (x in [0,1], x in [1,2], y in [0,1], y in [1,2], z).
  EXPECT_EQ(m["vertices"].get<int>(), 18);
  EXPECT_EQ(m["edges"].size(), 33u);
  std::set<int> classes;
  for (const auto& e : m["edges"]) classes.insert(e[0].get<int>());
  EXPECT_EQ(classes, (std::set<int>{0, 1, 2, 3, 4}));

  ASSERT_EQ(m["elements"].size(), mp.patches.size());
  ASSERT_EQ(m["patches"].size(), mp.patches.size());
  for (size_t i = 0; i < mp.patches.size(); ++i) {
    const auto& p = mp.patches[i];
    SCOPED_TRACE("patch " + std::to_string(i));
    EXPECT_EQ(m["elements"][i][0].get<int>(), p.material + 1);
    const json& q = m["patches"][i];
    for (int d = 0; d < 3; ++d) {
      EXPECT_EQ(q["degrees"][d].get<int>(), p.degrees[d]);
      EXPECT_EQ(q["ncp"][d].get<int>(), p.count(d));
      EXPECT_EQ(q["knots"][d].get<std::vector<double>>(), p.knots[d]);
    }
    for (Eigen::Index r = 0; r < p.control_points.rows(); ++r) {
      const double w = p.rational() ? p.weights[r] : 1.0;
      ASSERT_NEAR(q["weights"][r].get<double>(), w, 1e-15 * w);
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(q["points"][r][c].get<double>(), p.control_points(r, c), 1e-14 * (1 + std::abs(p.control_points(r, c))));
    }
  }
  // Boundary: attribute = label + 1, and the four vertices are the corners of that patch side.
  ASSERT_EQ(m["boundary"].size(), mp.boundaries.size());
  const int corner_bits[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (size_t k = 0; k < mp.boundaries.size(); ++k) {
    const auto& b = mp.boundaries[k];
    EXPECT_EQ(m["boundary"][k][0].get<int>(), b.label + 1);
    const int dir = b.side.direction();
    const int end = b.side.parameter() ? 1 : 0;
    std::set<int> want, have;
    for (int v = 0; v < 8; ++v)
      if (corner_bits[v][dir] == end) want.insert(m["elements"][b.patch][1 + v].get<int>());
    for (int v = 1; v <= 4; ++v) have.insert(m["boundary"][k][v].get<int>());
    EXPECT_EQ(have, want) << "boundary " << k;
  }
  std::filesystem::remove_all(dir);
}

TEST(MfemMesh, NonConformingKnotVectorsAreRefused) {
  MultiPatch mp = make_test_model();
  // Patch 1 gets a different v knot vector than patch 0 across their interface.
  mp.patches[1].knots[1] = {0, 0, 0, 0.25, 1, 1, 1};
  std::ostringstream out;
  try {
    igaprep::exporter::write_mfem_mesh(mp, out);
    ADD_FAILURE() << "accepted";
  } catch (const igaprep::Error& e) {
    EXPECT_EQ(e.kind(), igaprep::ErrorKind::BadInput);
    EXPECT_NE(std::string(e.what()).find("knot vectors differ"), std::string::npos) << e.what();
  }
}

}  // namespace
