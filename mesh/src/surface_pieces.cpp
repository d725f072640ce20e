#include "surface_pieces.h"

#include <cmath>

#include "igaprep/core/union_find.h"
#include "igaprep/mesh/enclosed_volume.h"

namespace igaprep::mesh::detail {

SurfacePieces surface_pieces(const TriMesh& mesh) {
  const int nv = static_cast<int>(mesh.V.rows()), nf = static_cast<int>(mesh.F.rows());
  UnionFind vertex_sets(nv);
  for (int f = 0; f < nf; ++f) {
    vertex_sets.unite(mesh.F(f, 0), mesh.F(f, 1));
    vertex_sets.unite(mesh.F(f, 0), mesh.F(f, 2));
  }
  SurfacePieces pieces;
  pieces.of_face.resize(static_cast<std::size_t>(nf));
  std::vector<int> piece_of_root(static_cast<std::size_t>(nv), -1);
  for (int f = 0; f < nf; ++f) {
    int& piece = piece_of_root[static_cast<std::size_t>(vertex_sets.find(mesh.F(f, 0)))];
    if (piece < 0) {
      piece = pieces.count();
      pieces.face_count.push_back(0);
    }
    pieces.of_face[static_cast<std::size_t>(f)] = piece;
    ++pieces.face_count[static_cast<std::size_t>(piece)];
  }
  return pieces;
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> referenced_bounding_box(const TriMesh& mesh) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = Eigen::Vector3d::Constant(-INFINITY);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d p = mesh.V.row(mesh.F(f, k)).transpose();
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  return {lo, hi};
}

std::vector<double> piece_volumes(const TriMesh& mesh, const SurfacePieces& pieces) {
  const auto [lo, hi] = referenced_bounding_box(mesh);
  return enclosed_volumes(mesh, pieces.of_face, pieces.count(), (lo + hi) / 2.0);
}

}  // namespace igaprep::mesh::detail
