#include "igaprep/mesh/orient_outward.h"

#include <utility>

#include "surface_pieces.h"

namespace igaprep::mesh {

std::vector<int> orient_outward(TriMesh& mesh) {
  const detail::SurfacePieces pieces = detail::surface_pieces(mesh);
  const std::vector<double> volume = detail::piece_volumes(mesh, pieces);
  std::vector<int> flipped;
  for (int c = 0; c < pieces.count(); ++c)
    if (volume[static_cast<std::size_t>(c)] < 0) flipped.push_back(c);
  if (flipped.empty()) return flipped;
  std::vector<char> flip(static_cast<std::size_t>(pieces.count()), 0);
  for (int c : flipped) flip[static_cast<std::size_t>(c)] = 1;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    if (flip[static_cast<std::size_t>(pieces.of_face[static_cast<std::size_t>(f)])]) std::swap(mesh.F(f, 1), mesh.F(f, 2));
  return flipped;
}

}  // namespace igaprep::mesh
