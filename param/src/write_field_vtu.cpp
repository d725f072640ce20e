#include "igaprep/param/write_field_vtu.h"

#include "igaprep/core/error.h"
#include "igaprep/mesh/write_vtu.h"

namespace igaprep::param {

void write_field_vtu(const std::string& path, const Eigen::MatrixXd& V, const Eigen::MatrixXi& cells,
                     const std::vector<std::pair<std::string, Eigen::VectorXd>>& point_fields,
                     const std::vector<std::pair<std::string, Eigen::MatrixXd>>& cell_vectors) {
  if (cells.cols() != 3 && cells.cols() != 4) throw bad_input("write_field_vtu: cells must have 3 or 4 columns");
  mesh::VtuMesh out;
  out.points = V;
  const auto type = cells.cols() == 4 ? mesh::kVtuTetra : mesh::kVtuTriangle;
  std::vector<int> ids(cells.cols());
  for (Eigen::Index c = 0; c < cells.rows(); ++c) {
    for (Eigen::Index k = 0; k < cells.cols(); ++k) ids[k] = cells(c, k);
    out.add_cell(type, ids);
  }
  for (const auto& [name, f] : point_fields) {
    if (f.size() != V.rows())
      throw bad_input("write_field_vtu: field '" + name + "' has " + std::to_string(f.size()) + " values for " +
                      std::to_string(V.rows()) + " vertices");
    out.add_point_data(name, f);
  }
  for (const auto& [name, g] : cell_vectors) {
    if (g.rows() != cells.rows() || g.cols() != 3)
      throw bad_input("write_field_vtu: cell vectors '" + name + "' must be #cells x 3");
    out.add_cell_data(name, g);
  }
  mesh::write_vtu(path, out);
}

void write_traces_vtu(const std::string& path, const std::vector<TraceResult>& traces) {
  Eigen::Index np = 0;
  for (const TraceResult& t : traces) np += t.path.rows();
  Eigen::MatrixXd P(np, 3);
  Eigen::VectorXi trace_id(np), status(static_cast<Eigen::Index>(traces.size())),
      steps(static_cast<Eigen::Index>(traces.size()));
  std::vector<std::vector<int>> lines;
  Eigen::Index at = 0;
  for (size_t i = 0; i < traces.size(); ++i) {
    const TraceResult& t = traces[i];
    std::vector<int> line;
    for (Eigen::Index r = 0; r < t.path.rows(); ++r, ++at) {
      P.row(at) = t.path.row(r);
      trace_id(at) = static_cast<int>(i);
      line.push_back(static_cast<int>(at));
    }
    lines.push_back(std::move(line));
    status(static_cast<Eigen::Index>(i)) = static_cast<int>(t.status);
    steps(static_cast<Eigen::Index>(i)) = t.steps;
  }
  mesh::VtuMesh out = mesh::vtu_polylines(P, lines);
  out.add_point_data("trace", trace_id);
  out.add_cell_data("status", status);
  out.add_cell_data("steps", steps);
  mesh::write_vtu(path, out);
}

}  // namespace igaprep::param
