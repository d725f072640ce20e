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
#include "cut_smoothing.h"
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
  return detail::smoothed_cut(std::move(edges), name, "waypoint loops, smoothed");
}

}  // namespace igaprep::param
