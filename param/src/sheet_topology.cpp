#include "igaprep/param/sheet_topology.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <unordered_map>

#include "igaprep/core/error.h"
#include "igaprep/core/union_find.h"

namespace igaprep::param {
SheetTopology analyze_sheet(const Eigen::MatrixXi& F, Eigen::Index num_vertices) {
  SheetTopology s;
  s.faces = static_cast<int>(F.rows());
  if (F.rows() == 0) return s;
  if (F.cols() != 3) throw bad_input("analyze_sheet: faces must have 3 columns");
  if (F.minCoeff() < 0 || F.maxCoeff() >= num_vertices) throw bad_input("analyze_sheet: a face index is out of range");
  const std::uint64_t n = static_cast<std::uint64_t>(num_vertices);
  // Half-edges a->b: count per directed edge, faces per undirected edge.
  std::unordered_map<std::uint64_t, int> directed;
  std::unordered_map<std::uint64_t, std::vector<int>> edge_faces;
  std::vector<char> used(static_cast<std::size_t>(num_vertices), 0);
  for (int f = 0; f < s.faces; ++f)
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t a = static_cast<std::uint64_t>(F(f, k)), b = static_cast<std::uint64_t>(F(f, (k + 1) % 3));
      used[a] = 1;
      directed[a * n + b] += 1;
      edge_faces[std::min(a, b) * n + std::max(a, b)].push_back(f);
    }
  s.vertices = static_cast<int>(std::count(used.begin(), used.end(), 1));
  s.edges = static_cast<int>(edge_faces.size());
  s.euler = s.vertices - s.edges + s.faces;
  s.edge_manifold = true;
  s.oriented = true;
  UnionFind uf(s.faces);
  for (const auto& [key, faces] : edge_faces) {
    if (faces.size() > 2) s.edge_manifold = false;
    for (std::size_t i = 1; i < faces.size(); ++i) uf.unite(faces[0], faces[i]);
    const std::uint64_t a = key / n, b = key % n;
    if (directed.count(a * n + b) && directed[a * n + b] > 1) s.oriented = false;
    if (directed.count(b * n + a) && directed[b * n + a] > 1) s.oriented = false;
  }
  for (int f = 0; f < s.faces; ++f)
    if (uf.find(f) == f) ++s.components;

  // Vertex fans: faces around a vertex connected through edges at that vertex.
  std::vector<std::vector<int>> vf(static_cast<std::size_t>(num_vertices));
  for (int f = 0; f < s.faces; ++f)
    for (int k = 0; k < 3; ++k) vf[F(f, k)].push_back(f);
  s.vertex_manifold = true;
  for (Eigen::Index v = 0; v < num_vertices && s.vertex_manifold; ++v) {
    const auto& fs = vf[v];
    if (fs.size() < 2) continue;
    // faces around v are linked when they share an edge (v, w)
    std::map<int, std::vector<int>> by_other;
    for (std::size_t i = 0; i < fs.size(); ++i)
      for (int k = 0; k < 3; ++k)
        if (F(fs[i], k) != v) by_other[F(fs[i], k)].push_back(static_cast<int>(i));
    UnionFind local(static_cast<int>(fs.size()));
    for (const auto& [w, list] : by_other)
      for (std::size_t i = 1; i < list.size(); ++i) local.unite(list[0], list[i]);
    for (std::size_t i = 1; i < fs.size(); ++i)
      if (local.find(static_cast<int>(i)) != local.find(0)) s.vertex_manifold = false;
  }

  // Boundary half-edges (no opposite half-edge), chained into loops.
  std::unordered_map<int, std::vector<int>> next;  // a -> b for boundary half-edge a->b
  for (int f = 0; f < s.faces; ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = F(f, k), b = F(f, (k + 1) % 3);
      if (!directed.count(static_cast<std::uint64_t>(b) * n + static_cast<std::uint64_t>(a))) next[a].push_back(b);
    }
  std::vector<int> starts;
  for (const auto& [a, list] : next) starts.push_back(a);
  std::sort(starts.begin(), starts.end());
  std::unordered_map<int, std::size_t> used_out;
  for (int a0 : starts) {
    while (used_out[a0] < next[a0].size()) {
      std::vector<int> loop;
      int a = a0;
      while (true) {
        auto& k = used_out[a];
        if (k >= next[a].size()) break;
        loop.push_back(a);
        const int b = next[a][k++];
        a = b;
        if (a == a0) break;
      }
      if (!loop.empty()) s.boundary_loops.push_back(loop);
    }
  }
  return s;
}

std::string describe_sheet_problem(const SheetTopology& s, int expected_loops, const std::string& name) {
  if (s.faces == 0) return name + " is empty";
  if (s.components != 1) return name + " has " + std::to_string(s.components) + " separate pieces, not one sheet";
  if (!s.edge_manifold) return name + " has an edge shared by more than two triangles";
  if (!s.vertex_manifold) return name + " is pinched at a vertex (not a manifold)";
  if (!s.oriented) return name + " is not consistently oriented";
  const int b = static_cast<int>(s.boundary_loops.size());
  const int twice_genus = 2 - b - s.euler;
  if (twice_genus != 0)
    return name + " has genus " + std::to_string(twice_genus / 2) + " (handles); a midsurface sheet must have none";
  if (b != expected_loops)
    return name + " has " + std::to_string(b) + " boundary loops, expected " + std::to_string(expected_loops);
  return "";
}

}  // namespace igaprep::param
