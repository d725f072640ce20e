#include "edge_graph.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <unordered_set>

#include "igaprep/core/edge_key.h"

namespace igaprep::param::detail {

EdgeGraph edge_graph(const mesh::TriMesh& m) {
  EdgeGraph graph(static_cast<std::size_t>(m.V.rows()));
  std::unordered_set<std::uint64_t> directed;
  auto length = [&](int a, int b) { return (m.V.row(a) - m.V.row(b)).norm(); };
  // In a closed oriented surface each edge runs a -> b in one face and b -> a
  // in the other, so this lists every neighbour once.
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = m.F(f, k), b = m.F(f, (k + 1) % 3);
      graph[static_cast<std::size_t>(a)].emplace_back(b, length(a, b));
      directed.insert((static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b));
    }
  // A boundary edge has no twin: its other end gets it here.
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = m.F(f, k), b = m.F(f, (k + 1) % 3);
      if (!directed.count((static_cast<std::uint64_t>(b) << 32) | static_cast<std::uint32_t>(a)))
        graph[static_cast<std::size_t>(b)].emplace_back(a, length(a, b));
    }
  return graph;
}

ShortestPaths shortest_paths(const EdgeGraph& graph, int source, int target, const std::vector<char>* blocked) {
  const double inf = std::numeric_limits<double>::infinity();
  ShortestPaths out{std::vector<double>(graph.size(), inf), std::vector<int>(graph.size(), -1)};
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  out.dist[static_cast<std::size_t>(source)] = 0.0;
  queue.emplace(0.0, source);
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (v == target) break;
    if (d > out.dist[static_cast<std::size_t>(v)]) continue;
    for (const auto& [w, len] : graph[static_cast<std::size_t>(v)])
      if (d + len < out.dist[static_cast<std::size_t>(w)] && (!blocked || w == target || !(*blocked)[static_cast<std::size_t>(w)])) {
        out.dist[static_cast<std::size_t>(w)] = d + len;
        out.prev[static_cast<std::size_t>(w)] = v;
        queue.emplace(d + len, w);
      }
  }
  return out;
}

std::vector<int> path_to(const ShortestPaths& paths, int target) {
  std::vector<int> path;
  for (int v = target; v != -1; v = paths.prev[static_cast<std::size_t>(v)]) path.push_back(v);
  std::reverse(path.begin(), path.end());
  return path;
}

}  // namespace igaprep::param::detail
