#include "igaprep/param/decomposition_mesh.h"

#include <algorithm>
#include <array>
#include <string>
#include <map>
#include <set>
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

std::vector<int> vertex_surfaces(const DecompositionMesh& H) {
  std::vector<int> label(static_cast<std::size_t>(H.tets.V.rows()), -1);
  for (std::size_t k = 0; k + 1 < H.surface_vertex_offset.size(); ++k)
    for (int v = H.surface_vertex_offset[k]; v < H.surface_vertex_offset[k + 1]; ++v)
      label[static_cast<std::size_t>(v)] = static_cast<int>(k);
  return label;
}

std::vector<std::vector<std::pair<int, int>>> surface_edges(const DecompositionMesh& H) {
  std::vector<std::vector<std::pair<int, int>>> edges(static_cast<std::size_t>(H.num_surfaces) + 1);
  for (Eigen::Index f = 0; f < H.tets.F.rows(); ++f) {
    const int m = H.tets.F_marker(f);
    if (m < 0 || m > H.num_surfaces) throw bad_input("surface_edges: unexpected face marker " + std::to_string(m));
    for (int j = 0; j < 3; ++j) {
      const int a = H.tets.F(f, j), b = H.tets.F(f, (j + 1) % 3);
      edges[static_cast<std::size_t>(m)].emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  return edges;
}

int count_flat_tets(const Eigen::MatrixXi& T, const std::vector<int>& vertex_surface) {
  int flat = 0;
  for (Eigen::Index t = 0; t < T.rows(); ++t) {
    const int k = vertex_surface[static_cast<std::size_t>(T(t, 0))];
    bool same = k >= 0;
    for (int j = 1; j < 4 && same; ++j) same = vertex_surface[static_cast<std::size_t>(T(t, j))] == k;
    flat += same;
  }
  return flat;
}

int split_surface_chords(mesh::TetMesh& H, std::vector<int>& vertex_surface,
                         const std::vector<std::vector<std::pair<int, int>>>& edges) {
  if (static_cast<Eigen::Index>(vertex_surface.size()) != H.V.rows())
    throw bad_input("split_surface_chords: one surface label per vertex expected");
  std::vector<std::set<std::pair<int, int>>> surface_edges(edges.size());
  for (std::size_t k = 0; k < edges.size(); ++k) surface_edges[k].insert(edges[k].begin(), edges[k].end());
  auto is_chord = [&](int a, int b) {
    const int k = vertex_surface[static_cast<std::size_t>(a)];
    if (k < 0 || k != vertex_surface[static_cast<std::size_t>(b)]) return false;
    if (static_cast<std::size_t>(k) >= surface_edges.size()) return true;
    return !surface_edges[static_cast<std::size_t>(k)].count({std::min(a, b), std::max(a, b)});
  };
  static constexpr int kEdge[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  int split = 0;
  // Passes: collect the chords and the tets around each, split chords whose
  // tets no earlier chord of this pass touched, repeat until none is left.
  for (int pass = 0;; ++pass) {
    if (pass > 64) throw internal_error("split_surface_chords: chords remain after 64 passes");
    std::map<std::pair<int, int>, std::vector<int>> chord_tets;
    for (Eigen::Index t = 0; t < H.T.rows(); ++t)
      for (const auto& e : kEdge) {
        const int a = H.T(t, e[0]), b = H.T(t, e[1]);
        if (is_chord(a, b)) chord_tets[{std::min(a, b), std::max(a, b)}].push_back(static_cast<int>(t));
      }
    if (chord_tets.empty()) break;
    std::vector<char> touched(static_cast<std::size_t>(H.T.rows()), 0);
    std::vector<Eigen::RowVector3d> new_v;
    std::vector<Eigen::RowVector4i> new_t;
    std::vector<int> new_mat;
    const int nv0 = static_cast<int>(H.V.rows());
    for (const auto& [e, tets] : chord_tets) {
      bool free = true;
      for (int t : tets) free = free && !touched[static_cast<std::size_t>(t)];
      if (!free) continue;
      const int m = nv0 + static_cast<int>(new_v.size());
      new_v.push_back(0.5 * (H.V.row(e.first) + H.V.row(e.second)));
      for (int t : tets) {
        touched[static_cast<std::size_t>(t)] = 1;
        // Replacing one end by the midpoint keeps the orientation.
        Eigen::RowVector4i half = H.T.row(t);
        for (int j = 0; j < 4; ++j)
          if (half(j) == e.second) half(j) = m;
        new_t.push_back(half);
        new_mat.push_back(H.material(t));
        for (int j = 0; j < 4; ++j)
          if (H.T(t, j) == e.first) H.T(t, j) = m;
      }
      ++split;
    }
    H.V.conservativeResize(nv0 + static_cast<Eigen::Index>(new_v.size()), 3);
    for (std::size_t i = 0; i < new_v.size(); ++i) H.V.row(nv0 + static_cast<Eigen::Index>(i)) = new_v[i];
    vertex_surface.resize(static_cast<std::size_t>(H.V.rows()), -1);
    const Eigen::Index nt0 = H.T.rows();
    H.T.conservativeResize(nt0 + static_cast<Eigen::Index>(new_t.size()), 4);
    H.material.conservativeResize(H.T.rows());
    for (std::size_t i = 0; i < new_t.size(); ++i) {
      H.T.row(nt0 + static_cast<Eigen::Index>(i)) = new_t[i];
      H.material(nt0 + static_cast<Eigen::Index>(i)) = new_mat[i];
    }
  }
  return split;
}

DecompositionMesh decomposition_mesh(const std::vector<mesh::TriMesh>& surfaces, const mesh::TriMesh& M,
                                     const mesh::TetgenOptions& options, bool split_chords) {
  if (surfaces.empty()) throw bad_input("decomposition_mesh: no surfaces given");
  if (M.F.rows() == 0) throw bad_input("decomposition_mesh: the base surface M has no triangles");
  DecompositionMesh H;
  H.num_surfaces = static_cast<int>(surfaces.size());
  try {
    H.tets = mesh::tetrahedralize(surfaces, {M}, options);
  } catch (const Error& e) {  // say which surface "embedded surface 0" is
    throw Error(e.kind(), std::string("H (T1..Tn with the base surface M as embedded surface 0): ") + e.what());
  }
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
  std::vector<int> label = vertex_surfaces(H);
  if (split_chords) {
    H.chords_split = split_surface_chords(H.tets, label, surface_edges(H));
  }
  H.flat_tets = count_flat_tets(H.tets.T, label);
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
