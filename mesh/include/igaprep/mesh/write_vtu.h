#pragma once
// VTK XML UnstructuredGrid (.vtu, ASCII) output of triangle meshes, tet meshes
// and polylines with named point and cell data, for looking at every stage in
// ParaView. Files are written atomically.
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "igaprep/mesh/tet_mesh.h"
#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::mesh {

// One named data array: #items x components (1 = scalar, 3 = vector), stored
// as Float64 (`real`) or Int32 (`integer`); exactly one of them is non-empty.
struct VtuArray {
  std::string name;
  Eigen::MatrixXd real;
  Eigen::MatrixXi integer;
};

// VTK cell type codes used here.
enum VtuCellType : std::uint8_t { kVtuVertex = 1, kVtuPolyLine = 4, kVtuTriangle = 5, kVtuTetra = 10 };

struct VtuMesh {
  Eigen::MatrixXd points;         // #P x 3
  std::vector<int> connectivity;  // point indices of all cells, one after the other
  std::vector<int> offsets;       // #C: end of each cell in `connectivity` (VTK convention)
  std::vector<std::uint8_t> types;  // #C: VtuCellType
  std::vector<VtuArray> point_data;  // each with #P rows
  std::vector<VtuArray> cell_data;   // each with #C rows

  void add_cell(VtuCellType type, const std::vector<int>& points);
  // Named arrays; a vector argument is a scalar array, a matrix one has one
  // component per column (1 or 3).
  void add_point_data(const std::string& name, const Eigen::MatrixXd& values);
  void add_point_data(const std::string& name, const Eigen::MatrixXi& values);
  void add_cell_data(const std::string& name, const Eigen::MatrixXd& values);
  void add_cell_data(const std::string& name, const Eigen::MatrixXi& values);
  void add_point_data(const std::string& name, const Eigen::VectorXd& values);
  void add_point_data(const std::string& name, const Eigen::VectorXi& values);
  void add_cell_data(const std::string& name, const Eigen::VectorXd& values);
  void add_cell_data(const std::string& name, const Eigen::VectorXi& values);
};

// Builders. Inputs: plain arrays. Outputs: a VtuMesh to which more arrays can
// be added before writing.
VtuMesh vtu_triangles(const TriMesh& mesh);
// Tets with cell data "material".
VtuMesh vtu_tets(const TetMesh& mesh);
// The marked faces of a tet mesh as triangles with cell data "marker".
VtuMesh vtu_marked_faces(const TetMesh& mesh);
// Polylines: V (#V x 3) and lines, each a list of indices into V.
VtuMesh vtu_polylines(const Eigen::MatrixXd& V, const std::vector<std::vector<int>>& lines);

// Writes `mesh` to `path` (ASCII VTK XML, full double precision). Throws
// bad_input for arrays of the wrong size, Error on I/O failure.
void write_vtu(const std::string& path, const VtuMesh& mesh);

// Shorthands: a triangle mesh, and a tet mesh with its "material" array.
void write_vtu(const std::string& path, const TriMesh& mesh);
void write_vtu(const std::string& path, const TetMesh& mesh);

}  // namespace igaprep::mesh
