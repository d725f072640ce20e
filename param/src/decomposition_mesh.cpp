#include "igaprep/param/decomposition_mesh.h"

#include <algorithm>
#include <array>
#include <string>
#include <unordered_set>

#include "igaprep/core/error.h"

namespace igaprep::param {
namespace {

struct FaceHash {
  std::size_t operator()(const std::array<int, 3>& f) const {
    std::size_t h = static_cast<std::size_t>(f[0]);
    h = h * 1000003u ^ static_cast<std::size_t>(f[1]);
    h = h * 1000003u ^ static_cast<std::size_t>(f[2]);
    return h;
  }
};

std::array<int, 3> sorted_face(int a, int b, int c) {
  std::array<int, 3> f{a, b, c};
  std::sort(f.begin(), f.end());
  return f;
}

}  // namespace

std::vector<int> faces_not_in_tets(const Eigen::MatrixXi& T, const Eigen::MatrixXi& faces) {
  if (T.cols() != 4) throw bad_input("faces_not_in_tets: tets must have 4 columns");
  if (faces.cols() != 3 && faces.rows() > 0) throw bad_input("faces_not_in_tets: faces must have 3 columns");
  std::unordered_set<std::array<int, 3>, FaceHash> tet_faces;
  tet_faces.reserve(static_cast<std::size_t>(T.rows()) * 4);
  for (Eigen::Index t = 0; t < T.rows(); ++t)
    for (int k = 0; k < 4; ++k)
      tet_faces.insert(sorted_face(T(t, (k + 1) % 4), T(t, (k + 2) % 4), T(t, (k + 3) % 4)));
  std::vector<int> missing;
  for (Eigen::Index f = 0; f < faces.rows(); ++f)
    if (!tet_faces.count(sorted_face(faces(f, 0), faces(f, 1), faces(f, 2)))) missing.push_back(static_cast<int>(f));
  return missing;
}

DecompositionMesh decomposition_mesh(const std::vector<mesh::TriMesh>& surfaces, const mesh::TriMesh& M,
                                     const mesh::TetgenOptions& options) {
  if (surfaces.empty()) throw bad_input("decomposition_mesh: no surfaces given");
  if (M.F.rows() == 0) throw bad_input("decomposition_mesh: the base surface M has no triangles");
  DecompositionMesh H;
  H.num_surfaces = static_cast<int>(surfaces.size());
  H.tets = mesh::tetrahedralize(surfaces, {M}, options);
  // tetrahedralize keeps the input points first, surface after surface.
  H.surface_vertex_offset.push_back(0);
  for (const auto& s : surfaces) H.surface_vertex_offset.push_back(H.surface_vertex_offset.back() + int(s.V.rows()));
  H.surface_vertex_offset.push_back(H.surface_vertex_offset.back() + static_cast<int>(M.V.rows()));
  if (H.tets.V.rows() < H.surface_vertex_offset.back())
    throw internal_error("decomposition_mesh: H has fewer vertices than its input surfaces");
  for (Eigen::Index i = 0; i < M.V.rows(); ++i)
    if (H.tets.V.row(H.surface_vertex_offset[H.num_surfaces] + i) != M.V.row(i))
      throw internal_error("decomposition_mesh: vertex " + std::to_string(i) + " of M moved in H");
  H.base_faces = M.F.array() + H.surface_vertex_offset[H.num_surfaces];

  H.surface_faces.assign(static_cast<std::size_t>(H.num_surfaces) + 1, {});
  for (Eigen::Index f = 0; f < H.tets.F.rows(); ++f) {
    const int m = H.tets.F_marker(f);
    if (m < 0 || m > H.num_surfaces) throw internal_error("decomposition_mesh: unexpected face marker");
    H.surface_faces[static_cast<std::size_t>(m)].push_back(static_cast<int>(f));
  }
  // M must be made of real tet faces: the w-field is pinned on it and the
  // decomposition surfaces start from its boundary.
  const std::vector<int> missing = faces_not_in_tets(H.tets.T, H.base_faces);
  if (!missing.empty())
    throw check_failed("decomposition_mesh: " + std::to_string(missing.size()) + " of the " +
                       std::to_string(M.F.rows()) + " triangles of the base surface M are no tet face of H (first: " +
                       std::to_string(missing.front()) + ")");
  return H;
}

}  // namespace igaprep::param
