// VTU output (write_vtu.h), read back with python's vtk.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "igaprep/core/error.h"
#include "igaprep/mesh/tetrahedralize.h"
#include "igaprep/mesh/write_vtu.h"
#include "igaprep/models/shapes.h"

namespace {

namespace fs = std::filesystem;

// Per-process temporary names: ctest may run these tests in parallel.
fs::path temp_file(const std::string& name) {
  return fs::temp_directory_path() / ("igaprep_" + std::to_string(::getpid()) + "_" + name);
}

std::string run(const std::string& command) {
  std::string out;
  FILE* p = popen(command.c_str(), "r");
  if (!p) return out;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
  const int status = pclose(p);
  if (status != 0) out += "\nEXIT STATUS " + std::to_string(status);
  return out;
}

// Reads a .vtu with vtkXMLUnstructuredGridReader and prints: points cells
// then the requested array values.
std::string read_with_vtk(const std::string& path, const std::string& extra) {
  const std::string script =
      "import vtk, sys\n"
      "r = vtk.vtkXMLUnstructuredGridReader()\n"
      "r.SetFileName(sys.argv[1])\n"
      "r.Update()\n"
      "g = r.GetOutput()\n"
      "print(g.GetNumberOfPoints(), g.GetNumberOfCells())\n" +
      extra;
  const fs::path py = temp_file("read_vtu.py");
  FILE* f = std::fopen(py.c_str(), "w");
  std::fputs(script.c_str(), f);
  std::fclose(f);
  const std::string out = run(std::string(IGAPREP_PYTHON) + " " + py.string() + " " + path + " 2>&1");
  fs::remove(py);
  return out;
}

}  // namespace

TEST(WriteVtu, TetMeshRoundTripThroughVtk) {
  const auto tm = igaprep::mesh::tetrahedralize(
      {igaprep::models::make_ellipsoid(1, 1, 1, 2), igaprep::models::make_ellipsoid(0.5, 0.5, 0.5, 1)});
  auto vtu = igaprep::mesh::vtu_tets(tm);
  Eigen::VectorXd radius = tm.V.rowwise().norm();
  vtu.add_point_data("radius", radius);
  vtu.add_point_data("position", Eigen::MatrixXd(tm.V));
  Eigen::VectorXi ids = Eigen::VectorXi::LinSpaced(tm.T.rows(), 0, static_cast<int>(tm.T.rows()) - 1);
  vtu.add_cell_data("id", ids);
  const fs::path path = temp_file("test_tets.vtu");
  igaprep::mesh::write_vtu(path.string(), vtu);

  const Eigen::Index p = tm.V.rows() / 2, c = tm.T.rows() - 1;
  const std::string out = read_with_vtk(
      path.string(),
      "print('%.17g' % g.GetPointData().GetArray('radius').GetValue(" + std::to_string(p) + "))\n"
      "print(' '.join('%.17g' % x for x in g.GetPointData().GetArray('position').GetTuple3(" + std::to_string(p) + ")))\n"
      "print(int(g.GetCellData().GetArray('material').GetValue(" + std::to_string(c) + ")))\n"
      "print(int(g.GetCellData().GetArray('id').GetValue(" + std::to_string(c) + ")))\n"
      "print(g.GetCellType(0), g.GetCell(" + std::to_string(c) + ").GetPointId(3))\n");
  std::istringstream in(out);
  long np = -1, nc = -1, material = -1, id = -1, type = -1, last_point = -1;
  double r = -1, x = 0, y = 0, z = 0;
  in >> np >> nc >> r >> x >> y >> z >> material >> id >> type >> last_point;
  ASSERT_FALSE(in.fail()) << out;
  EXPECT_EQ(np, tm.V.rows());
  EXPECT_EQ(nc, tm.T.rows());
  EXPECT_EQ(r, radius(p));  // full precision survives the round trip
  EXPECT_EQ(x, tm.V(p, 0));
  EXPECT_EQ(y, tm.V(p, 1));
  EXPECT_EQ(z, tm.V(p, 2));
  EXPECT_EQ(material, tm.material(c));
  EXPECT_EQ(id, c);
  EXPECT_EQ(type, 10);  // VTK_TETRA
  EXPECT_EQ(last_point, tm.T(c, 3));
  fs::remove(path);
}

TEST(WriteVtu, TrianglesFacesAndPolylines) {
  const auto sphere = igaprep::models::make_ellipsoid(1, 1, 1, 1);
  const fs::path tri = temp_file("test_tri.vtu");
  igaprep::mesh::write_vtu(tri.string(), sphere);
  std::istringstream a(read_with_vtk(tri.string(), "print(g.GetCellType(0))\n"));
  long np = 0, nc = 0, type = 0;
  a >> np >> nc >> type;
  EXPECT_EQ(np, sphere.V.rows());
  EXPECT_EQ(nc, sphere.F.rows());
  EXPECT_EQ(type, 5);

  Eigen::MatrixXd V(5, 3);
  V << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1;
  auto lines = igaprep::mesh::vtu_polylines(V, {{0, 1, 2, 3}, {3, 4}});
  lines.add_cell_data("length", Eigen::VectorXd((Eigen::VectorXd(2) << 3.0, 1.0).finished()));
  const fs::path pl = temp_file("test_lines.vtu");
  igaprep::mesh::write_vtu(pl.string(), lines);
  std::istringstream b(read_with_vtk(
      pl.string(), "print(g.GetCell(0).GetNumberOfPoints(), g.GetCellData().GetArray('length').GetValue(1))\n"));
  long n0 = 0;
  double len = 0;
  b >> np >> nc >> n0 >> len;
  EXPECT_EQ(np, 5);
  EXPECT_EQ(nc, 2);
  EXPECT_EQ(n0, 4);
  EXPECT_EQ(len, 1.0);
  fs::remove(tri);
  fs::remove(pl);
}

TEST(WriteVtu, BadArraysAndPathsAreErrors) {
  const auto sphere = igaprep::models::make_ellipsoid(1, 1, 1, 1);
  auto vtu = igaprep::mesh::vtu_triangles(sphere);
  vtu.add_point_data("short", Eigen::VectorXd(Eigen::VectorXd::Zero(3)));
  const fs::path path = temp_file("test_bad.vtu");
  EXPECT_THROW(igaprep::mesh::write_vtu(path.string(), vtu), igaprep::Error);
  EXPECT_FALSE(fs::exists(path));
  EXPECT_THROW(igaprep::mesh::write_vtu("/nonexistent-dir/x.vtu", sphere), igaprep::Error);
}
