#include "igaprep/mesh/write_vtu.h"

#include <algorithm>
#include <cstdio>
#include <ostream>

#include "igaprep/core/atomic_file.h"
#include "igaprep/core/error.h"

namespace igaprep::mesh {
namespace {

VtuArray make_array(const std::string& name, const Eigen::MatrixXd& values) {
  VtuArray a;
  a.name = name;
  a.real = values;
  return a;
}
VtuArray make_array(const std::string& name, const Eigen::MatrixXi& values) {
  VtuArray a;
  a.name = name;
  a.integer = values;
  return a;
}

void check_array(const VtuArray& a, Eigen::Index rows, const std::string& where, const std::string& path) {
  const bool is_int = a.integer.size() > 0 || a.real.size() == 0;
  const Eigen::Index r = is_int ? a.integer.rows() : a.real.rows();
  const Eigen::Index c = is_int ? a.integer.cols() : a.real.cols();
  if (a.name.empty() || a.name.find_first_of("\"<>&") != std::string::npos) {
    throw bad_input("write_vtu " + path + ": " + where + " array name '" + a.name + "' is empty or not XML-safe");
  }
  if (r != rows || (rows > 0 && c < 1)) {
    throw bad_input("write_vtu " + path + ": " + where + " array '" + a.name + "' has " + std::to_string(r) +
                    " rows, expected " + std::to_string(rows));
  }
}

void write_real(std::ostream& os, double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  os << buf;
}

void write_array(std::ostream& os, const VtuArray& a) {
  const bool is_int = a.integer.size() > 0 || a.real.size() == 0;
  const Eigen::Index rows = is_int ? a.integer.rows() : a.real.rows();
  const Eigen::Index cols = std::max<Eigen::Index>(1, is_int ? a.integer.cols() : a.real.cols());
  os << "        <DataArray type=\"" << (is_int ? "Int32" : "Float64") << "\" Name=\"" << a.name
     << "\" NumberOfComponents=\"" << cols << "\" format=\"ascii\">\n";
  for (Eigen::Index i = 0; i < rows; ++i) {
    os << "         ";
    for (Eigen::Index j = 0; j < cols; ++j) {
      os << ' ';
      if (is_int) os << a.integer(i, j); else write_real(os, a.real(i, j));
    }
    os << '\n';
  }
  os << "        </DataArray>\n";
}

}  // namespace

void VtuMesh::add_cell(VtuCellType type, const std::vector<int>& cell_points) {
  connectivity.insert(connectivity.end(), cell_points.begin(), cell_points.end());
  offsets.push_back(static_cast<int>(connectivity.size()));
  types.push_back(type);
}
void VtuMesh::add_point_data(const std::string& name, const Eigen::MatrixXd& values) {
  point_data.push_back(make_array(name, values));
}
void VtuMesh::add_point_data(const std::string& name, const Eigen::MatrixXi& values) {
  point_data.push_back(make_array(name, values));
}
void VtuMesh::add_cell_data(const std::string& name, const Eigen::MatrixXd& values) {
  cell_data.push_back(make_array(name, values));
}
void VtuMesh::add_cell_data(const std::string& name, const Eigen::MatrixXi& values) {
  cell_data.push_back(make_array(name, values));
}

void VtuMesh::add_point_data(const std::string& name, const Eigen::VectorXd& values) {
  add_point_data(name, Eigen::MatrixXd(values));
}
void VtuMesh::add_point_data(const std::string& name, const Eigen::VectorXi& values) {
  add_point_data(name, Eigen::MatrixXi(values));
}
void VtuMesh::add_cell_data(const std::string& name, const Eigen::VectorXd& values) {
  add_cell_data(name, Eigen::MatrixXd(values));
}
void VtuMesh::add_cell_data(const std::string& name, const Eigen::VectorXi& values) {
  add_cell_data(name, Eigen::MatrixXi(values));
}

VtuMesh vtu_triangles(const TriMesh& mesh) {
  VtuMesh out;
  out.points = mesh.V;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) out.add_cell(kVtuTriangle, {mesh.F(f, 0), mesh.F(f, 1), mesh.F(f, 2)});
  return out;
}

VtuMesh vtu_tets(const TetMesh& mesh) {
  VtuMesh out;
  out.points = mesh.V;
  for (Eigen::Index t = 0; t < mesh.T.rows(); ++t) {
    out.add_cell(kVtuTetra, {mesh.T(t, 0), mesh.T(t, 1), mesh.T(t, 2), mesh.T(t, 3)});
  }
  if (mesh.material.size() == mesh.T.rows()) out.add_cell_data("material", Eigen::MatrixXi(mesh.material));
  return out;
}

VtuMesh vtu_marked_faces(const TetMesh& mesh) {
  VtuMesh out;
  out.points = mesh.V;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) out.add_cell(kVtuTriangle, {mesh.F(f, 0), mesh.F(f, 1), mesh.F(f, 2)});
  if (mesh.F_marker.size() == mesh.F.rows()) out.add_cell_data("marker", Eigen::MatrixXi(mesh.F_marker));
  return out;
}

VtuMesh vtu_polylines(const Eigen::MatrixXd& V, const std::vector<std::vector<int>>& lines) {
  VtuMesh out;
  out.points = V;
  for (const auto& line : lines) out.add_cell(kVtuPolyLine, line);
  return out;
}

void write_vtu(const std::string& path, const VtuMesh& mesh) {
  const Eigen::Index np = mesh.points.rows();
  const Eigen::Index nc = static_cast<Eigen::Index>(mesh.types.size());
  if (np > 0 && mesh.points.cols() != 3) throw bad_input("write_vtu " + path + ": points must have 3 columns");
  if (static_cast<Eigen::Index>(mesh.offsets.size()) != nc) {
    throw bad_input("write_vtu " + path + ": " + std::to_string(mesh.offsets.size()) + " offsets for " +
                    std::to_string(nc) + " cell types");
  }
  int previous = 0;
  for (int o : mesh.offsets) {
    if (o < previous || o > static_cast<int>(mesh.connectivity.size())) {
      throw bad_input("write_vtu " + path + ": cell offsets are not increasing within the connectivity");
    }
    previous = o;
  }
  if (previous != static_cast<int>(mesh.connectivity.size())) {
    throw bad_input("write_vtu " + path + ": the last offset does not end the connectivity");
  }
  for (int v : mesh.connectivity) {
    if (v < 0 || v >= np) throw bad_input("write_vtu " + path + ": cell point index " + std::to_string(v) + " out of range");
  }
  for (const auto& a : mesh.point_data) check_array(a, np, "point", path);
  for (const auto& a : mesh.cell_data) check_array(a, nc, "cell", path);

  write_file_atomically(path, [&](std::ostream& os) {
    os << "<?xml version=\"1.0\"?>\n"
       << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
       << "  <UnstructuredGrid>\n"
       << "    <Piece NumberOfPoints=\"" << np << "\" NumberOfCells=\"" << nc << "\">\n";
    os << "      <PointData>\n";
    for (const auto& a : mesh.point_data) write_array(os, a);
    os << "      </PointData>\n      <CellData>\n";
    for (const auto& a : mesh.cell_data) write_array(os, a);
    os << "      </CellData>\n      <Points>\n";
    VtuArray pts;
    pts.name = "Points";
    pts.real = np > 0 ? mesh.points : Eigen::MatrixXd(0, 3);
    write_array(os, pts);
    os << "      </Points>\n      <Cells>\n";
    os << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (std::size_t i = 0; i < mesh.connectivity.size(); ++i) os << (i % 12 == 0 ? "         " : "") << ' ' << mesh.connectivity[i] << (i % 12 == 11 ? "\n" : "");
    os << "\n        </DataArray>\n";
    os << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::size_t i = 0; i < mesh.offsets.size(); ++i) os << (i % 12 == 0 ? "         " : "") << ' ' << mesh.offsets[i] << (i % 12 == 11 ? "\n" : "");
    os << "\n        </DataArray>\n";
    os << "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (std::size_t i = 0; i < mesh.types.size(); ++i) os << (i % 12 == 0 ? "         " : "") << ' ' << static_cast<int>(mesh.types[i]) << (i % 12 == 11 ? "\n" : "");
    os << "\n        </DataArray>\n";
    os << "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  });
}

void write_vtu(const std::string& path, const TriMesh& mesh) { write_vtu(path, vtu_triangles(mesh)); }
void write_vtu(const std::string& path, const TetMesh& mesh) { write_vtu(path, vtu_tets(mesh)); }

}  // namespace igaprep::mesh
