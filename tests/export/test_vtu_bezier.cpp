// VTU Bezier hexahedra read back by VTK (python3-vtk9): cell count and type,
// degrees, and points evaluated by VTK inside each cell against our
// evaluation; displacement and von Mises stress against the exact values of
// the test model's affine displacement.
#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "igaprep/core/error.h"
#include "igaprep/export/vtu_bezier.h"
#include "igaprep/spline/bezier_extraction.h"
#include "igaprep/spline/evaluate.h"
#include "test_model.h"
#include "test_util.h"

namespace {
using igaprep::spline::MultiPatch;
using namespace igaprep::test;

struct CellRef {
  int patch;
  std::array<std::array<double, 2>, 3> domain;
};

std::vector<CellRef> expected_cells(const MultiPatch& mp) {
  std::vector<CellRef> cells;
  for (size_t p = 0; p < mp.patches.size(); ++p) {
    const auto ex = igaprep::spline::bezier_extraction(mp.patches[p]);
    for (int ew = 0; ew < ex.element_count(2); ++ew)
      for (int ev = 0; ev < ex.element_count(1); ++ev)
        for (int eu = 0; eu < ex.element_count(0); ++eu) {
          CellRef c{static_cast<int>(p), {}};
          const int e[3] = {eu, ev, ew};
          for (int d = 0; d < 3; ++d) c.domain[d] = {ex.dirs[d].breaks[e[d]], ex.dirs[d].breaks[e[d] + 1]};
          cells.push_back(c);
        }
  }
  return cells;
}

void check_with_vtk(const MultiPatch& mp, bool binary, bool solution) {
  const std::string dir = scratch_dir(binary ? "vtu_bin" : "vtu_ascii");
  igaprep::exporter::write_vtu_bezier(mp, dir + "/m.vtu", {binary});
  const CommandResult r = run_python("check_vtu.py", {dir + "/m.vtu", "5", "7"});
  ASSERT_EQ(r.status, 0) << r.output.substr(0, 2000);
  const std::vector<CellRef> cells = expected_cells(mp);
  std::istringstream in(r.output);
  std::string word;
  int n = -1;
  in >> word >> n;
  ASSERT_EQ(word, "cells");
  ASSERT_EQ(n, static_cast<int>(cells.size()));
  for (int c = 0; c < n; ++c) {
    int id, type, d0, d1, d2, mat, patch;
    in >> word >> id >> type >> d0 >> d1 >> d2 >> mat >> patch;
    ASSERT_EQ(word, "cell");
    ASSERT_EQ(id, c);
    EXPECT_EQ(type, 79);
    const auto& p = mp.patches[cells[c].patch];
    EXPECT_EQ(d0, p.degrees[0]);
    EXPECT_EQ(d1, p.degrees[1]);
    EXPECT_EQ(d2, p.degrees[2]);
    EXPECT_EQ(patch, cells[c].patch);
    EXPECT_EQ(mat, p.material);
  }
  const Eigen::Matrix3d A = test_displacement_gradient();
  const Eigen::Vector3d b = test_displacement_offset();
  double worst_x = 0, worst_u = 0, worst_vm = 0;
  int samples = 0;
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    int c;
    Eigen::Vector3d t, x;
    ls >> word >> c >> t[0] >> t[1] >> t[2] >> x[0] >> x[1] >> x[2];
    ASSERT_EQ(word, "sample");
    ASSERT_GE(c, 0);
    ASSERT_LT(c, n);
    const CellRef& cell = cells[c];
    Eigen::Vector3d xi;
    for (int d = 0; d < 3; ++d) xi[d] = cell.domain[d][0] + t[d] * (cell.domain[d][1] - cell.domain[d][0]);
    const Eigen::Vector3d ours = igaprep::spline::evaluate_point(mp.patches[cell.patch], xi);
    worst_x = std::max(worst_x, (ours - x).norm() / std::max(1.0, ours.norm()));
    if (solution) {
      Eigen::Vector3d u;
      double vm;
      ASSERT_TRUE(static_cast<bool>(ls >> u[0] >> u[1] >> u[2] >> vm)) << line;
      const Eigen::Vector3d exact_u = A * ours + b;
      worst_u = std::max(worst_u, (u - exact_u).norm() / exact_u.norm());
      const auto& m = mp.materials[mp.patches[cell.patch].material];
      const double exact_vm = test_von_mises(m.young_modulus, m.poisson_ratio);
      worst_vm = std::max(worst_vm, std::abs(vm - exact_vm) / exact_vm);
    }
    ++samples;
  }
  EXPECT_EQ(samples, 5 * n);
  EXPECT_LT(worst_x, 1e-9) << "VTK's points vs our evaluation";
  if (solution) {
    EXPECT_LT(worst_u, 1e-9) << "displacement";
    EXPECT_LT(worst_vm, 1e-8) << "von Mises stress";
  }
  std::filesystem::remove_all(dir);
}

TEST(VtuBezier, VtkReadsBinaryFileAndAgreesWithOurEvaluation) { check_with_vtk(make_test_model(), true, true); }

TEST(VtuBezier, VtkReadsAsciiGeometryOnlyFile) {
  MultiPatch mp = make_test_model();
  for (auto& p : mp.patches) p.displacement.resize(0, 0);
  mp.has_solution = false;
  check_with_vtk(mp, false, false);
}

TEST(VtuBezier, PointOrderMatchesVtk) {
  // VTK's own PointIndexFromIJK (through Python) for a few anisotropic degrees.
  std::ostringstream script;
  script << "import vtk\n"
            "for o in [(1,1,1),(2,3,1),(3,2,4),(2,2,2)]:\n"
            "  for k in range(o[2]+1):\n"
            "    for j in range(o[1]+1):\n"
            "      for i in range(o[0]+1):\n"
            "        print(vtk.vtkHigherOrderHexahedron.PointIndexFromIJK(i,j,k,list(o)))\n";
  const CommandResult r = run_command(std::string(IGAPREP_PYTHON) + " -c " + shell_quote(script.str()));
  ASSERT_EQ(r.status, 0) << r.output;
  std::istringstream in(r.output);
  int compared = 0;
  for (std::array<int, 3> o : {std::array<int, 3>{1, 1, 1}, {2, 3, 1}, {3, 2, 4}, {2, 2, 2}}) {
    std::set<int> seen;
    for (int k = 0; k <= o[2]; ++k)
      for (int j = 0; j <= o[1]; ++j)
        for (int i = 0; i <= o[0]; ++i) {
          int vtk_index = -1;
          ASSERT_TRUE(static_cast<bool>(in >> vtk_index));
          const int ours = igaprep::exporter::vtk_hex_point_index(i, j, k, o);
          EXPECT_EQ(ours, vtk_index) << i << " " << j << " " << k;
          seen.insert(ours);
          ++compared;
        }
    EXPECT_EQ(static_cast<int>(seen.size()), (o[0] + 1) * (o[1] + 1) * (o[2] + 1));
  }
  EXPECT_EQ(compared, 8 + 24 + 60 + 27);
}

// Issue 23, item 2: ParaView's Slice coloured by material showed values of
// +-2e9 (higher-order cell data through VTK's cutter); the same array as
// point data slices exactly. Every cell also carries its element index and
// its smallest sampled scaled Jacobian.
// Element faces of a patch on one of its sides.
std::size_t element_faces_on(const igaprep::spline::Patch& p, igaprep::spline::Side side) {
  const auto ex = igaprep::spline::bezier_extraction(p);
  std::size_t n = 1;
  for (const int d : side.tangent_directions()) n *= static_cast<std::size_t>(ex.element_count(d));
  return n;
}

TEST(VtuBezier, ASliceKeepsTheMaterialsAndEveryCellItsQuality) {
  const std::string dir = scratch_dir("vtu_slice");
  MultiPatch mp = make_test_model();  // a model, not a solve result: its points are shared
  for (auto& p : mp.patches) p.displacement.resize(0, 0);
  mp.has_solution = false;
  igaprep::exporter::VtuOptions options;
  for (std::size_t c = 0; c < expected_cells(mp).size(); ++c) options.certified_lower_bound.push_back(0.25 * c);
  igaprep::exporter::write_vtu_bezier(mp, dir + "/m.vtu", options);
  const CommandResult r = run_python("slice_vtu.py", {dir + "/m.vtu"});
  ASSERT_EQ(r.status, 0) << r.output.substr(0, 2000);
  const nlohmann::json j = nlohmann::json::parse(r.output);
  EXPECT_GT(j["points"].get<int>(), 0);
  EXPECT_EQ(j["materials"], nlohmann::json({0.0, 1.0}));  // the plane crosses both, nothing between
  const std::size_t cells = expected_cells(mp).size();
  EXPECT_EQ(j["element_shape"], nlohmann::json({cells, 3}));
  EXPECT_GT(j["min_scaled_jacobian"][0].get<double>(), 0.0);
  EXPECT_LE(j["min_scaled_jacobian"][1].get<double>(), 1.0 + 1e-12);
  EXPECT_EQ(j["certified_det_lower_bound"].get<std::vector<double>>(), options.certified_lower_bound);
  // Points are shared where cells meet within a material, so Extract Surface
  // gives the labelled sides and both faces of the material interface, not
  // every element face (issue 23, item 2).
  std::size_t boundary = 0, material_interface = 0;
  for (const auto& b : mp.boundaries) boundary += element_faces_on(mp.patches[static_cast<std::size_t>(b.patch)], b.side);
  for (const auto& itf : mp.interfaces)
    if (mp.patches[static_cast<std::size_t>(itf.patch_a)].material != mp.patches[static_cast<std::size_t>(itf.patch_b)].material)
      material_interface += 2 * element_faces_on(mp.patches[static_cast<std::size_t>(itf.patch_a)], itf.side_a);
  EXPECT_GT(material_interface, 0u);
  EXPECT_EQ(j["surface_faces"].get<std::size_t>(), boundary + material_interface);
  options.certified_lower_bound.pop_back();  // one per cell or none
  EXPECT_THROW(igaprep::exporter::write_vtu_bezier(mp, dir + "/m2.vtu", options), igaprep::Error);
  std::filesystem::remove_all(dir);
}

}  // namespace
