#include "cut_smoothing.h"

#include "igaprep/core/error.h"
#include "edge_graph.h"

namespace igaprep::param::detail {
namespace {

// The side of every vertex, smoothed by a few rounds of neighbour averaging.
Eigen::VectorXd smoothed_sides(const CutLoops& cut, int rounds) {
  const mesh::TriMesh& m = cut.surface;
  Eigen::VectorXd x = cut.vertex_side.cast<double>();
  const EdgeGraph adj = edge_graph(m);
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

CutLoops smoothed_cut(CutLoops edges, const std::string& name, const std::string& smoothed_source, int rounds) {
  try {
    CutLoops smooth = cut_by_field(edges.surface, smoothed_sides(edges, rounds), name, smoothed_source);
    if (smooth.loops.size() == edges.loops.size()) return smooth;
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::BadInput) throw;
  }
  return edges;
}

}  // namespace igaprep::param::detail
