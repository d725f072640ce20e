// The labelled boundary as Bezier quadrilaterals, read back by VTK
// (python3-vtk9): one cell per element face on a labelled side, nothing of
// the interior, and VTK's points inside each cell equal to our evaluation
// of the side (issue 23, item 2).
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "igaprep/export/vtu_boundary.h"
#include "igaprep/spline/bezier_extraction.h"
#include "igaprep/spline/evaluate.h"
#include "test_model.h"
#include "test_util.h"

namespace {
using igaprep::spline::MultiPatch;
using namespace igaprep::test;

struct FaceRef {
  int patch, side, label;
  std::array<std::array<double, 2>, 3> domain;  // the normal direction's interval collapsed to the side
};

// The faces in the writer's order: boundaries as listed, elements w, v, u.
std::vector<FaceRef> expected_faces(const MultiPatch& mp) {
  std::vector<FaceRef> out;
  for (const auto& b : mp.boundaries) {
    const auto ex = igaprep::spline::bezier_extraction(mp.patches[static_cast<std::size_t>(b.patch)]);
    const int n = b.side.direction();
    std::array<int, 3> lo{0, 0, 0}, hi{ex.element_count(0), ex.element_count(1), ex.element_count(2)};
    lo[static_cast<std::size_t>(n)] = b.side.parameter() ? hi[static_cast<std::size_t>(n)] - 1 : 0;
    hi[static_cast<std::size_t>(n)] = lo[static_cast<std::size_t>(n)] + 1;
    for (int ew = lo[2]; ew < hi[2]; ++ew)
      for (int ev = lo[1]; ev < hi[1]; ++ev)
        for (int eu = lo[0]; eu < hi[0]; ++eu) {
          FaceRef f{b.patch, b.side.index(), b.label, {}};
          const int e[3] = {eu, ev, ew};
          for (int d = 0; d < 3; ++d) f.domain[d] = {ex.dirs[d].breaks[e[d]], ex.dirs[d].breaks[e[d] + 1]};
          const double end = f.domain[n][b.side.parameter() ? 1 : 0];
          f.domain[n] = {end, end};
          out.push_back(f);
        }
  }
  return out;
}

TEST(VtuBoundary, OnlyTheLabelledSidesAndVtkAgreesWithOurEvaluation) {
  const std::string dir = scratch_dir("vtu_boundary");
  const MultiPatch mp = make_test_model();
  {
    std::ofstream out(dir + "/b.vtu", std::ios::binary);
    igaprep::exporter::write_vtu_boundary(mp, out);
  }
  const CommandResult r = run_python("check_boundary_vtu.py", {dir + "/b.vtu", "4", "11"});
  ASSERT_EQ(r.status, 0) << r.output.substr(0, 2000);
  const std::vector<FaceRef> faces = expected_faces(mp);
  std::istringstream in(r.output);
  std::string word;
  int n = -1;
  in >> word >> n;
  ASSERT_EQ(n, static_cast<int>(faces.size()));
  std::set<int> labels;
  for (int c = 0; c < n; ++c) {
    int id, type, d0, d1, label, patch, side;
    in >> word >> id >> type >> d0 >> d1 >> label >> patch >> side;
    ASSERT_EQ(word, "cell");
    EXPECT_EQ(type, 77);  // VTK_BEZIER_QUADRILATERAL
    EXPECT_EQ(patch, faces[c].patch);
    EXPECT_EQ(side, faces[c].side);
    EXPECT_EQ(label, faces[c].label);
    labels.insert(label);
  }
  std::set<int> expected_labels;
  for (const auto& b : mp.boundaries) expected_labels.insert(b.label);
  EXPECT_EQ(labels, expected_labels);
  double worst = 0.0;
  int samples = 0;
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    int c;
    double rr, ss;
    Eigen::Vector3d x;
    ls >> word >> c >> rr >> ss >> x[0] >> x[1] >> x[2];
    ASSERT_EQ(word, "sample");
    const FaceRef& f = faces[static_cast<std::size_t>(c)];
    const int normal = (f.side - 1) / 2, a = normal == 0 ? 1 : 0, b = normal == 2 ? 1 : 2;
    Eigen::Vector3d xi;
    xi[normal] = f.domain[normal][0];
    xi[a] = f.domain[a][0] + rr * (f.domain[a][1] - f.domain[a][0]);
    xi[b] = f.domain[b][0] + ss * (f.domain[b][1] - f.domain[b][0]);
    const Eigen::Vector3d ours = igaprep::spline::evaluate_point(mp.patches[static_cast<std::size_t>(f.patch)], xi);
    worst = std::max(worst, (ours - x).norm() / std::max(1.0, ours.norm()));
    ++samples;
  }
  EXPECT_EQ(samples, 4 * n);
  EXPECT_LT(worst, 1e-9) << "VTK's points vs our evaluation of the sides";
  std::filesystem::remove_all(dir);
}

TEST(VtuBoundary, PointOrderMatchesVtk) {
  std::ostringstream script;
  script << "import vtk\n"
            "for o in [(1,1),(2,3),(3,2),(3,3)]:\n"
            "  for j in range(o[1]+1):\n"
            "    for i in range(o[0]+1):\n"
            "      print(vtk.vtkHigherOrderQuadrilateral.PointIndexFromIJK(i,j,list(o)+[0]))\n";
  const CommandResult r = run_command(std::string(IGAPREP_PYTHON) + " -c " + shell_quote(script.str()));
  ASSERT_EQ(r.status, 0) << r.output;
  std::istringstream in(r.output);
  for (std::array<int, 2> o : {std::array<int, 2>{1, 1}, {2, 3}, {3, 2}, {3, 3}})
    for (int j = 0; j <= o[1]; ++j)
      for (int i = 0; i <= o[0]; ++i) {
        int vtk_index = -1;
        ASSERT_TRUE(static_cast<bool>(in >> vtk_index));
        EXPECT_EQ(igaprep::exporter::vtk_quad_point_index(i, j, o), vtk_index) << i << " " << j;
      }
}

}  // namespace
