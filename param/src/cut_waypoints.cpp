// Cut loops drawn as waypoints (cut_loops.h, cut_by_waypoints).
#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <utility>
#include <vector>

#include "igaprep/core/error.h"
#include "igaprep/param/cut_loops.h"
#include "edge_graph.h"

namespace igaprep::param {
namespace {

using Adjacency = detail::EdgeGraph;
using detail::edge_graph;

int nearest_vertex(const mesh::TriMesh& m, const Eigen::Vector3d& p) {
  Eigen::Index best;
  (m.V.rowwise() - p.transpose()).rowwise().squaredNorm().minCoeff(&best);
  return static_cast<int>(best);
}

// Shortest edge path from a to b (both included), Dijkstra on edge lengths.
std::vector<int> shortest_path(const Adjacency& adj, int a, int b) {
  return detail::path_to(detail::shortest_paths(adj, a, b), b);
}

// The loop through the snapped waypoints, as a vertex cycle.
std::vector<int> waypoint_cycle(const mesh::TriMesh& T1, const Adjacency& adj,
                                const std::vector<Eigen::Vector3d>& points, const std::string& where) {
  if (points.size() < 3) throw bad_input(where + " needs at least 3 waypoints");
  std::vector<int> snapped;
  for (const Eigen::Vector3d& p : points) {
    const int v = nearest_vertex(T1, p);
    if (snapped.empty() || snapped.back() != v) snapped.push_back(v);
  }
  if (snapped.size() > 1 && snapped.front() == snapped.back()) snapped.pop_back();
  if (snapped.size() < 3) throw bad_input(where + ": the waypoints snap to fewer than 3 distinct vertices of T1");
  std::vector<int> cycle;
  for (std::size_t i = 0; i < snapped.size(); ++i) {
    const std::vector<int> leg = shortest_path(adj, snapped[i], snapped[(i + 1) % snapped.size()]);
    if (leg.size() < 2) throw bad_input(where + ": waypoint " + std::to_string(i) + " is not connected to the next");
    cycle.insert(cycle.end(), leg.begin(), leg.end() - 1);  // the leg's end starts the next leg
  }
  return cycle;
}

// The side of every vertex (+1 / -1, 0 on the loops), smoothed by a few rounds
// of neighbour averaging: its zero set follows the edge path without the
// path's staircase along the triangles.
Eigen::VectorXd smoothed_sides(const CutLoops& cut, int rounds) {
  const mesh::TriMesh& m = cut.surface;
  Eigen::VectorXd x = cut.vertex_side.cast<double>();
  const Adjacency adj = edge_graph(m);
  for (int r = 0; r < rounds; ++r) {
    Eigen::VectorXd next = x;
    for (std::size_t v = 0; v < adj.size(); ++v) {
      if (adj[v].empty()) continue;
      double sum = 0.0;
      for (const auto& [w, len] : adj[v]) sum += x(w);
      next(static_cast<Eigen::Index>(v)) = 0.5 * x(static_cast<Eigen::Index>(v)) + 0.5 * sum / static_cast<double>(adj[v].size());
    }
    x = next;
  }
  return x;
}

}  // namespace

CutLoops cut_by_waypoints(const mesh::TriMesh& T1, const std::vector<std::vector<Eigen::Vector3d>>& waypoints,
                          const std::string& name) {
  if (waypoints.empty()) throw bad_input(name + ": no cut loops given");
  const Adjacency adj = edge_graph(T1);
  std::vector<std::vector<int>> loops;
  for (std::size_t l = 0; l < waypoints.size(); ++l)
    loops.push_back(waypoint_cycle(T1, adj, waypoints[l], name + ": waypoint loop " + std::to_string(l)));
  CutLoops edges = cut_by_loops(T1, loops, name);
  edges.source = "waypoint loops";
  // The smooth version when it is as valid; the edge paths otherwise.
  try {
    CutLoops smooth = cut_by_field(edges.surface, smoothed_sides(edges, 3), name, "waypoint loops, smoothed");
    if (smooth.loops.size() == edges.loops.size()) return smooth;
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::BadInput) throw;
  }
  return edges;
}

}  // namespace igaprep::param
