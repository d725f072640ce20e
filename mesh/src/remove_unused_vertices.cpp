#include "igaprep/mesh/remove_unused_vertices.h"

#include <utility>
#include <vector>

namespace igaprep::mesh {

int remove_unused_vertices(TriMesh& mesh) {
  const Eigen::Index nv = mesh.V.rows();
  std::vector<char> used(static_cast<std::size_t>(nv), 0);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) used[static_cast<std::size_t>(mesh.F(f, k))] = 1;
  std::vector<int> new_index(static_cast<std::size_t>(nv), -1);
  int kept = 0;
  for (std::size_t i = 0; i < used.size(); ++i)
    if (used[i]) new_index[i] = kept++;
  if (kept == nv) return 0;
  Eigen::MatrixXd W(kept, mesh.V.cols());
  for (Eigen::Index i = 0; i < nv; ++i)
    if (new_index[static_cast<std::size_t>(i)] >= 0) W.row(new_index[static_cast<std::size_t>(i)]) = mesh.V.row(i);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) mesh.F(f, k) = new_index[static_cast<std::size_t>(mesh.F(f, k))];
  mesh.V = std::move(W);
  return static_cast<int>(nv - kept);
}

}  // namespace igaprep::mesh
