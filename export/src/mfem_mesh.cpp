// MFEM NURBS mesh writer. MFEM's conventions (fem/geom.cpp, mesh/nurbs.cpp):
// hexahedron vertices v0..v7 = (0,0,0) (1,0,0) (1,1,0) (0,1,0) and the same
// at w = 1; its edges {0,1} {1,2} {3,2} {0,3} {4,5} {5,6} {7,6} {4,7} {0,4}
// {1,5} {2,6} {3,7}, all running in the increasing parameter direction, so
// edges 0,2,4,6 are u, 1,3,5,7 v and 8..11 w; patch knot vector d belongs
// to edges 0, 3, 8. An "edges" line "k a b" says knot vector k runs from
// vertex a to vertex b. Boundary faces are written outward (MFEM's face
// vertex cycles) and started at the corner where both knot vectors start,
// which is what NURBSExtension::CheckBdrPatches requires.
#include "igaprep/export/mfem_mesh.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "igaprep/core/atomic_file.h"
#include "igaprep/core/error.h"
#include "igaprep/core/union_find.h"
#include "igaprep/spline/multipatch_topology.h"
#include "model_checks.h"
#include "number_text.h"

namespace igaprep::exporter {

namespace {
using detail::exact;

constexpr int kEdgeVerts[12][2] = {{0, 1}, {1, 2}, {3, 2}, {0, 3}, {4, 5}, {5, 6},
                                   {7, 6}, {4, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
int edge_direction(int e) { return e < 8 ? (e & 1) : 2; }
// Corner (bits u, v, w) of MFEM's hexahedron vertex.
constexpr int kCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                               {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
// MFEM's outward face cycles, by Side::array_index() (u0 u1 v0 v1 w0 w1).
constexpr int kFaceVerts[6][4] = {{3, 0, 4, 7}, {1, 2, 6, 5}, {0, 1, 5, 4},
                                  {2, 3, 7, 6}, {3, 2, 1, 0}, {4, 5, 6, 7}};

// Knot vector normalised to [0, 1], reversed if asked.
std::vector<double> normalised(const std::vector<double>& U, bool reverse) {
  const double a = U.front(), b = U.back();
  std::vector<double> out(U.size());
  for (size_t i = 0; i < U.size(); ++i) {
    const double t = (U[i] - a) / (b - a);
    if (reverse) out[U.size() - 1 - i] = 1.0 - t;
    else out[i] = t;
  }
  return out;
}

struct Topology {
  int vertex_count = 0;
  std::vector<std::array<int, 8>> hex;       // per patch, MFEM vertex order
  std::vector<std::array<int, 2>> edges;     // written as "kv a b": kv runs a -> b
  std::vector<int> edge_kv;
  std::vector<std::array<int, 12>> patch_edges;  // per patch, local edge -> global edge
};

Topology build_topology(const spline::MultiPatch& mp) {
  Topology t;
  const int np = static_cast<int>(mp.patches.size());
  // Corner vertices: corner control points identified across interfaces by
  // the spline module's global numbering, renumbered by first appearance.
  const spline::GlobalNumbering numbering = spline::global_numbering(mp);
  std::map<int, int> vertex_of_global;
  t.hex.resize(np);
  for (int p = 0; p < np; ++p) {
    const spline::Patch& patch = mp.patches[p];
    for (int v = 0; v < 8; ++v) {
      const int i = kCorner[v][0] ? patch.count(0) - 1 : 0;
      const int j = kCorner[v][1] ? patch.count(1) - 1 : 0;
      const int k = kCorner[v][2] ? patch.count(2) - 1 : 0;
      const int g = numbering.global[p][patch.index(i, j, k)];
      auto it = vertex_of_global.find(g);
      if (it == vertex_of_global.end()) it = vertex_of_global.emplace(g, t.vertex_count++).first;
      t.hex[p][v] = it->second;
    }
    for (int a = 0; a < 8; ++a)
      for (int b = a + 1; b < 8; ++b)
        if (t.hex[p][a] == t.hex[p][b])
          throw bad_input("MFEM mesh: patch " + std::to_string(p) +
                          " has two corners joined by its interfaces (degenerate patch topology)");
  }
  // Edges by vertex pair, oriented as first met (increasing parameter).
  std::map<std::pair<int, int>, int> edge_of_pair;
  std::vector<std::array<int, 12>> sign(np);
  t.patch_edges.resize(np);
  for (int p = 0; p < np; ++p)
    for (int e = 0; e < 12; ++e) {
      const int a = t.hex[p][kEdgeVerts[e][0]], b = t.hex[p][kEdgeVerts[e][1]];
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = edge_of_pair.find(key);
      if (it == edge_of_pair.end()) {
        it = edge_of_pair.emplace(key, static_cast<int>(t.edges.size())).first;
        t.edges.push_back({a, b});
      }
      t.patch_edges[p][e] = it->second;
      sign[p][e] = t.edges[it->second][0] == a ? 1 : -1;
    }
  // Parallel edges of a patch share a knot vector running the same way.
  UnionFind uf(static_cast<int>(t.edges.size()));  // parity: the edge runs along (+1) or against its knot vector
  for (int p = 0; p < np; ++p)
    for (int d = 0; d < 3; ++d) {
      const int first = d == 0 ? 0 : d == 1 ? 1 : 8;
      for (int e = 0; e < 12; ++e)
        if (edge_direction(e) == d && e != first &&
            !uf.unite(t.patch_edges[p][first], t.patch_edges[p][e], sign[p][first] * sign[p][e]))
          throw bad_input("MFEM mesh: the knot vectors of patch " + std::to_string(p) + " direction " +
                          detail::direction_name(d) +
                          " cannot be oriented consistently across the interfaces (twisted patch loop)");
    }
  std::map<int, int> kv_of_root;
  t.edge_kv.resize(t.edges.size());
  for (size_t e = 0; e < t.edges.size(); ++e) {
    const auto [root, s] = uf.find_with_parity(static_cast<int>(e));
    auto it = kv_of_root.find(root);
    if (it == kv_of_root.end()) it = kv_of_root.emplace(root, static_cast<int>(kv_of_root.size())).first;
    t.edge_kv[e] = it->second;
    if (s < 0) std::swap(t.edges[e][0], t.edges[e][1]);  // write it the way the knot vector runs
  }
  // The knot vectors of one class must agree (normalised, oriented).
  std::map<int, std::pair<int, std::vector<double>>> kv_knots;  // kv -> (patch, knots)
  for (int p = 0; p < np; ++p)
    for (int d = 0; d < 3; ++d) {
      const int first = d == 0 ? 0 : d == 1 ? 1 : 8;
      const int e = t.patch_edges[p][first];
      const bool reversed = t.edges[e][0] != t.hex[p][kEdgeVerts[first][0]];
      const spline::Patch& patch = mp.patches[p];
      std::vector<double> U = normalised(patch.knots[d], reversed);
      auto [it, fresh] = kv_knots.emplace(t.edge_kv[e], std::make_pair(p, U));
      if (fresh) continue;
      const std::vector<double>& V = it->second.second;
      bool same = U.size() == V.size();
      for (size_t k = 0; same && k < U.size(); ++k) same = std::abs(U[k] - V[k]) <= 1e-10;
      if (!same)
        throw bad_input("MFEM mesh: patch " + std::to_string(p) + " direction " + detail::direction_name(d) +
                        " and patch " + std::to_string(it->second.first) +
                        " share an edge class but their knot vectors differ (MFEM needs conforming patches)");
    }
  return t;
}
}  // namespace

void write_mfem_mesh(const spline::MultiPatch& model, std::ostream& out) {
  detail::check_model_for_writing(model, "MFEM mesh");
  const Topology t = build_topology(model);
  const int np = static_cast<int>(model.patches.size());
  out << "MFEM NURBS mesh v1.0\n\n";
  out << "# Written by igaprep: one hexahedral patch per element (attribute = material + 1),\n";
  out << "# boundary attribute = label + 1. Labels:\n";
  for (size_t l = 0; l < model.labels.size(); ++l) out << "#   " << l + 1 << " " << model.labels[l] << "\n";
  out << "# Materials:\n";
  for (size_t m = 0; m < model.materials.size(); ++m)
    out << "#   " << m + 1 << " " << model.materials[m].name << " E " << exact(model.materials[m].young_modulus)
        << " nu " << exact(model.materials[m].poisson_ratio) << "\n";
  out << "\ndimension\n3\n\n";
  out << "elements\n" << np << "\n";
  for (int p = 0; p < np; ++p) {
    out << model.patches[p].material + 1 << " 5";
    for (int v = 0; v < 8; ++v) out << " " << t.hex[p][v];
    out << "\n";
  }
  out << "\nboundary\n" << model.boundaries.size() << "\n";
  std::map<std::pair<int, int>, int> kv_edge;  // directed (a, b) along its knot vector
  for (size_t e = 0; e < t.edges.size(); ++e) kv_edge[{t.edges[e][0], t.edges[e][1]}] = static_cast<int>(e);
  for (const spline::BoundarySide& b : model.boundaries) {
    int q[4];
    for (int k = 0; k < 4; ++k) q[k] = t.hex[b.patch][kFaceVerts[b.side.array_index()][k]];
    int start = -1;
    for (int r = 0; r < 4 && start < 0; ++r)
      if (kv_edge.count({q[r], q[(r + 1) % 4]}) && kv_edge.count({q[(r + 1) % 4], q[(r + 2) % 4]})) start = r;
    if (start < 0) throw internal_error("MFEM mesh: no boundary face orientation for patch " + std::to_string(b.patch));
    out << b.label + 1 << " 3";
    for (int k = 0; k < 4; ++k) out << " " << q[(start + k) % 4];
    out << "\n";
  }
  out << "\nedges\n" << t.edges.size() << "\n";
  for (size_t e = 0; e < t.edges.size(); ++e) out << t.edge_kv[e] << " " << t.edges[e][0] << " " << t.edges[e][1] << "\n";
  out << "\nvertices\n" << t.vertex_count << "\n";
  out << "\npatches\n";
  for (int p = 0; p < np; ++p) {
    const spline::Patch& patch = model.patches[p];
    out << "\n# patch " << p << "\nknotvectors\n3\n";
    for (int d = 0; d < 3; ++d) {
      out << patch.degrees[d] << " " << patch.count(d);
      for (double k : patch.knots[d]) out << " " << exact(k);
      out << "\n";
    }
    out << "\ndimension\n3\n\ncontrolpoints\n";
    for (Eigen::Index r = 0; r < patch.control_points.rows(); ++r) {
      const double w = patch.rational() ? patch.weights[r] : 1.0;
      out << exact(patch.control_points(r, 0) * w) << " " << exact(patch.control_points(r, 1) * w) << " "
          << exact(patch.control_points(r, 2) * w) << " " << exact(w) << "\n";
    }
  }
}

void write_mfem_mesh(const spline::MultiPatch& model, const std::string& path) {
  detail::check_model_for_writing(model, "'" + path + "'");
  write_file_atomically(path, [&](std::ostream& out) { write_mfem_mesh(model, out); });
}

}  // namespace igaprep::exporter
