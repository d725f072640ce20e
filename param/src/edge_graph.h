#pragma once
// A triangle mesh's edges as a weighted graph, and shortest edge paths on it
// (cut loops from waypoints, the necks of a sheet's lobes).
#include <utility>
#include <vector>

#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::param::detail {

// Per vertex its neighbours and the edges' lengths, each edge once per end
// (on a sheet's boundary too).
using EdgeGraph = std::vector<std::vector<std::pair<int, double>>>;
EdgeGraph edge_graph(const mesh::TriMesh& m);

struct ShortestPaths {
  std::vector<double> dist;  // infinity where not reached
  std::vector<int> prev;     // the vertex before on a shortest path, -1 at the source and where not reached
};

// Dijkstra from source; with target >= 0 it stops once target is settled.
// Vertices marked in `blocked` (when given) are never entered, except target.
ShortestPaths shortest_paths(const EdgeGraph& graph, int source, int target = -1,
                             const std::vector<char>* blocked = nullptr);

// The path from the search's source to target (both included).
std::vector<int> path_to(const ShortestPaths& paths, int target);

}  // namespace igaprep::param::detail
