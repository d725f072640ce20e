// Fields and traces written as VTU and read back with VTK's own reader.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "igaprep/core/error.h"
#include "igaprep/param/gradient.h"
#include "igaprep/param/harmonic_field.h"
#include "igaprep/param/write_field_vtu.h"
#include "param_meshes.h"

using namespace igaprep::param;

namespace {

// Runs /usr/bin/python3 with vtk on `script`; returns its stdout ("" when vtk is absent).
std::string run_python(const std::string& script) {
  const std::string py = std::filesystem::temp_directory_path() / "igaprep_param_vtu_check.py";
  std::ofstream(py) << script;
  const std::string out = py + ".out";
  const int rc = std::system((std::string(IGAPREP_PYTHON) + " " + py + " > " + out + " 2>&1").c_str());
  std::ifstream in(out);
  std::stringstream ss;
  ss << in.rdbuf();
  if (rc != 0) ADD_FAILURE() << "python failed: " << ss.str();
  return ss.str();
}

}  // namespace

TEST(Vtu, FieldAndTracesReadBackInVtk) {
  const auto m = param_test::box_tets(3, 3, 3);
  Eigen::VectorXd u(m.V.rows());
  for (Eigen::Index i = 0; i < u.size(); ++i) u(i) = m.V(i, 0) + 2 * m.V(i, 2);
  const auto dir = std::filesystem::temp_directory_path() / "igaprep_param_vtu";
  std::filesystem::create_directories(dir);
  const std::string field = (dir / "field.vtu").string(), traces = (dir / "traces.vtu").string();
  write_field_vtu(field, m.V, m.T, {{"u", u}}, {{"grad_u", cell_gradients(m.V, m.T, u)}});
  TraceResult a, b;
  a.path = Eigen::MatrixXd::Random(4, 3);
  b.path = Eigen::MatrixXd::Random(7, 3);
  b.status = TraceStatus::Reached;
  write_traces_vtu(traces, {a, b});
  EXPECT_THROW(write_field_vtu(field, m.V, m.T, {{"bad", Eigen::VectorXd::Zero(3)}}), igaprep::Error);
  const std::string out = run_python(
      "import vtk\n"
      "from vtk.util.numpy_support import vtk_to_numpy as n\n"
      "r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName('" + field + "'); r.Update(); g = r.GetOutput()\n"
      "u = n(g.GetPointData().GetArray('u')); p = n(g.GetPoints().GetData())\n"
      "gr = n(g.GetCellData().GetArray('grad_u'))\n"
      "print(g.GetNumberOfPoints(), g.GetNumberOfCells(), abs(u - p[:,0] - 2*p[:,2]).max() < 1e-14,"
      " abs(gr - [1, 0, 2]).max() < 1e-12)\n"
      "r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName('" + traces + "'); r.Update(); t = r.GetOutput()\n"
      "print(t.GetNumberOfPoints(), t.GetNumberOfCells(), t.GetCellType(1), list(n(t.GetCellData().GetArray('status'))))\n");
  EXPECT_EQ(out, std::to_string(m.V.rows()) + " " + std::to_string(m.T.rows()) + " True True\n11 2 4 [3, 0]\n");
}
