// Tunnel loops (tunnel_loops.h): candidate loops are the generators of the
// surface's homology through many base points (a shortest-path tree and a
// dual spanning tree of the longest loops, Erickson and Whittlesey 2005);
// a candidate is a tunnel loop when, pushed off the surface outwards, it
// links no loop pushed inwards (it is then trivial outside the solid).
#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

#include "igaprep/core/edge_key.h"
#include "igaprep/core/error.h"
#include "igaprep/core/union_find.h"
#include "igaprep/param/tunnel_loops.h"
#include "edge_graph.h"
#include "face_graph.h"

namespace igaprep::param {
namespace {

using V3 = Eigen::Vector3d;

// The signed solid angle that segment b0-b1 sweeps as seen along segment
// a0-a1 (Klenin and Langowski 2000): the pair's share of 4 pi times the
// linking number.
double segment_pair_angle(const V3& a0, const V3& a1, const V3& b0, const V3& b1) {
  const V3 r00 = b0 - a0, r01 = b1 - a0, r10 = b0 - a1, r11 = b1 - a1;
  auto unit_cross = [](const V3& x, const V3& y) -> V3 {
    const V3 c = x.cross(y);
    const double n = c.norm();
    return n > 0.0 ? V3(c / n) : V3::Zero();
  };
  const V3 n1 = unit_cross(r00, r01), n2 = unit_cross(r01, r11), n3 = unit_cross(r11, r10), n4 = unit_cross(r10, r00);
  auto arcsin = [](double x) { return std::asin(std::clamp(x, -1.0, 1.0)); };
  const double omega = arcsin(n1.dot(n2)) + arcsin(n2.dot(n3)) + arcsin(n3.dot(n4)) + arcsin(n4.dot(n1));
  const double orientation = (b1 - b0).cross(a1 - a0).dot(r00);
  return orientation > 0.0 ? omega : (orientation < 0.0 ? -omega : 0.0);
}

using Edge = detail::FaceEdge;  // faces a and b, vertices u and v

struct SurfaceGraph {
  detail::EdgeGraph adjacency;
  std::vector<Edge> edges;
  Eigen::MatrixXd normal;  // per vertex, area-weighted
  double mean_edge = 0.0;
};

SurfaceGraph surface_graph(const mesh::TriMesh& m) {
  SurfaceGraph g;
  g.adjacency = detail::edge_graph(m);
  g.normal = Eigen::MatrixXd::Zero(m.V.rows(), 3);
  for (int f = 0; f < static_cast<int>(m.F.rows()); ++f) {
    const V3 a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    const V3 n = (b - a).cross(c - a);
    for (int k = 0; k < 3; ++k) g.normal.row(m.F(f, k)) += n.transpose();
  }
  // Each edge as its first face has it (face_neighbours gives the second's):
  // the loops then run the way they always did.
  g.edges = detail::face_neighbours(m);
  for (Edge& e : g.edges) std::swap(e.u, e.v);
  g.normal.rowwise().normalize();
  for (const Edge& e : g.edges) g.mean_edge += e.length;
  g.mean_edge /= static_cast<double>(std::max<std::size_t>(g.edges.size(), 1));
  return g;
}

struct Candidate {
  std::vector<int> cycle;
  double length = 0.0;
};

// The cycle closed by edge (u, v) of the shortest-path tree: u up to the two
// paths' meeting vertex, then down to v.
Candidate tree_cycle(const detail::ShortestPaths& tree, const Edge& e, std::vector<char>& mark) {
  Candidate c;
  for (int x = e.u; x != -1; x = tree.prev[static_cast<std::size_t>(x)]) mark[static_cast<std::size_t>(x)] = 1;
  std::vector<int> down;
  int meet = e.v;
  while (!mark[static_cast<std::size_t>(meet)]) {
    down.push_back(meet);
    meet = tree.prev[static_cast<std::size_t>(meet)];
  }
  for (int x = e.u;; x = tree.prev[static_cast<std::size_t>(x)]) {
    c.cycle.push_back(x);
    if (x == meet) break;
  }
  for (int x = e.u; x != -1; x = tree.prev[static_cast<std::size_t>(x)]) mark[static_cast<std::size_t>(x)] = 0;
  c.cycle.insert(c.cycle.end(), down.rbegin(), down.rend());
  c.length = tree.dist[static_cast<std::size_t>(e.u)] + tree.dist[static_cast<std::size_t>(e.v)] + e.length -
             2.0 * tree.dist[static_cast<std::size_t>(meet)];
  return c;
}

// The 2g generator loops through a base point: the edges in neither the
// shortest-path tree nor the dual spanning tree of the longest loops.
std::vector<Candidate> generators_through(const mesh::TriMesh& m, const SurfaceGraph& g,
                                          const detail::ShortestPaths& tree, std::vector<char>& mark) {
  std::vector<int> dual;
  for (int i = 0; i < static_cast<int>(g.edges.size()); ++i) {
    const Edge& e = g.edges[static_cast<std::size_t>(i)];
    if (tree.prev[static_cast<std::size_t>(e.u)] == e.v || tree.prev[static_cast<std::size_t>(e.v)] == e.u) continue;
    dual.push_back(i);
  }
  auto loop_length = [&](int i) {
    const Edge& e = g.edges[static_cast<std::size_t>(i)];
    return tree.dist[static_cast<std::size_t>(e.u)] + tree.dist[static_cast<std::size_t>(e.v)] + e.length;
  };
  // Loops of one length (a symmetric mesh has many) in the order of their
  // edges' vertices, not of the edge list's order.
  std::sort(dual.begin(), dual.end(), [&](int a, int b) {
    const double la = loop_length(a), lb = loop_length(b);
    if (la != lb) return la > lb;
    const Edge &ea = g.edges[static_cast<std::size_t>(a)], &eb = g.edges[static_cast<std::size_t>(b)];
    return edge_key(ea.u, ea.v) < edge_key(eb.u, eb.v);
  });
  UnionFind faces(static_cast<int>(m.F.rows()));
  std::vector<Candidate> out;
  for (int i : dual) {
    const Edge& e = g.edges[static_cast<std::size_t>(i)];
    if (faces.find(e.a) != faces.find(e.b)) faces.unite(e.a, e.b);
    else out.push_back(tree_cycle(tree, e, mark));
  }
  return out;
}

Eigen::MatrixXd pushed(const mesh::TriMesh& m, const SurfaceGraph& g, const std::vector<int>& cycle, double offset) {
  Eigen::MatrixXd p(static_cast<Eigen::Index>(cycle.size()), 3);
  for (std::size_t i = 0; i < cycle.size(); ++i)
    p.row(static_cast<Eigen::Index>(i)) = m.V.row(cycle[i]) + offset * g.normal.row(cycle[i]);
  return p;
}

bool boxes_apart(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return ((a.colwise().maxCoeff() - b.colwise().minCoeff()).array() < 0.0).any() ||
         ((b.colwise().maxCoeff() - a.colwise().minCoeff()).array() < 0.0).any();
}

// Linking numbers of one loop, pushed off the surface, with the basis loops
// pushed the other way, rounded (polygons whose boxes are apart link 0).
Eigen::VectorXd links_with(const Eigen::MatrixXd& loop, const std::vector<Eigen::MatrixXd>& basis) {
  Eigen::VectorXd l(static_cast<Eigen::Index>(basis.size()));
  for (std::size_t j = 0; j < basis.size(); ++j)
    l(static_cast<Eigen::Index>(j)) = boxes_apart(loop, basis[j]) ? 0.0 : std::round(linking_number(loop, basis[j]));
  return l;
}

// Farthest-point sampling of base points by graph distance; the trees of
// the sampled points come along.
class BasePoints {
 public:
  BasePoints(const SurfaceGraph& g, int first)
      : g_(g), nearest_(g.adjacency.size(), std::numeric_limits<double>::infinity()), next_(first) {}
  detail::ShortestPaths next() {
    detail::ShortestPaths tree = detail::shortest_paths(g_.adjacency, next_);
    for (std::size_t v = 0; v < nearest_.size(); ++v) nearest_[v] = std::min(nearest_[v], tree.dist[v]);
    next_ = static_cast<int>(std::max_element(nearest_.begin(), nearest_.end()) - nearest_.begin());
    return tree;
  }

 private:
  const SurfaceGraph& g_;
  std::vector<double> nearest_;
  int next_;
};

class TunnelSearch {
 public:
  TunnelSearch(const mesh::TriMesh& m, const SurfaceGraph& g, const std::vector<Candidate>& basis, double offset)
      : m_(m), g_(g), offset_(offset) {
    for (const Candidate& b : basis) {
      inward_.push_back(pushed(m, g, b.cycle, -offset));
      outward_.push_back(pushed(m, g, b.cycle, offset));
    }
  }

  // The loop's class inside the solid (its links with the basis pushed
  // out) when it is trivial outside (no link with the basis pushed in);
  // empty otherwise.
  Eigen::VectorXd tunnel_class(const Candidate& c) const {
    if (links_with(pushed(m_, g_, c.cycle, offset_), inward_).any()) return {};
    return links_with(pushed(m_, g_, c.cycle, -offset_), outward_);
  }

 private:
  const mesh::TriMesh& m_;
  const SurfaceGraph& g_;
  double offset_;
  std::vector<Eigen::MatrixXd> inward_, outward_;
};

int rank_of(const std::vector<Eigen::VectorXd>& classes) {
  if (classes.empty()) return 0;
  Eigen::MatrixXd a(classes.front().size(), static_cast<Eigen::Index>(classes.size()));
  for (std::size_t i = 0; i < classes.size(); ++i) a.col(static_cast<Eigen::Index>(i)) = classes[i];
  Eigen::FullPivLU<Eigen::MatrixXd> lu(a);
  lu.setThreshold(1e-6);
  return static_cast<int>(lu.rank());
}

struct Chosen {
  std::vector<Candidate> loops;
  std::vector<Eigen::VectorXd> classes;
};

bool touches(const std::vector<char>& used, const Candidate& c) {
  return std::any_of(c.cycle.begin(), c.cycle.end(), [&](int v) { return used[static_cast<std::size_t>(v)] != 0; });
}

std::vector<char> vertices_of(const std::vector<Candidate>& loops, std::size_t vertices, std::size_t skip) {
  std::vector<char> used(vertices, 0);
  for (std::size_t i = 0; i < loops.size(); ++i)
    if (i != skip)
      for (int v : loops[i].cycle) used[static_cast<std::size_t>(v)] = 1;
  return used;
}

// Shortest first: a tunnel loop of a new class, apart from those taken.
Chosen choose_loops(std::vector<Candidate> candidates, const TunnelSearch& search, int genus, std::size_t vertices) {
  std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) { return a.length < b.length; });
  Chosen chosen;
  std::vector<char> used(vertices, 0);
  for (const Candidate& c : candidates) {
    if (static_cast<int>(chosen.loops.size()) == genus) break;
    if (touches(used, c)) continue;
    const Eigen::VectorXd cls = search.tunnel_class(c);
    if (cls.size() == 0) continue;
    std::vector<Eigen::VectorXd> with = chosen.classes;
    with.push_back(cls);
    if (rank_of(with) <= static_cast<int>(chosen.classes.size())) continue;
    chosen.loops.push_back(c);
    chosen.classes.push_back(cls);
    for (int v : c.cycle) used[static_cast<std::size_t>(v)] = 1;
  }
  return chosen;
}

// A shorter loop in place of loop i: through base points on the loop itself,
// a tunnel loop that keeps the classes independent and the loops apart.
bool tighten(const mesh::TriMesh& m, const SurfaceGraph& g, const TunnelSearch& search, Chosen& chosen, std::size_t i) {
  const std::vector<int> cycle = chosen.loops[i].cycle;
  const std::vector<char> used = vertices_of(chosen.loops, g.adjacency.size(), i);
  std::vector<char> mark(g.adjacency.size(), 0);
  std::vector<Candidate> candidates;
  const std::size_t step = std::max<std::size_t>(1, cycle.size() / 12);
  for (std::size_t k = 0; k < cycle.size(); k += step) {
    const detail::ShortestPaths tree = detail::shortest_paths(g.adjacency, cycle[k]);
    for (Candidate& c : generators_through(m, g, tree, mark))
      if (c.length < chosen.loops[i].length * (1.0 - 1e-9) && !touches(used, c)) candidates.push_back(std::move(c));
  }
  std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) { return a.length < b.length; });
  for (const Candidate& c : candidates) {
    const Eigen::VectorXd cls = search.tunnel_class(c);
    if (cls.size() == 0) continue;
    std::vector<Eigen::VectorXd> with = chosen.classes;
    with[i] = cls;
    if (rank_of(with) < static_cast<int>(with.size())) continue;
    chosen.loops[i] = c;
    chosen.classes[i] = cls;
    return true;
  }
  return false;
}

}  // namespace

double linking_number(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  double sum = 0.0;
  const Eigen::Index na = a.rows(), nb = b.rows();
  for (Eigen::Index i = 0; i < na; ++i) {
    const V3 a0 = a.row(i), a1 = a.row((i + 1) % na);
    for (Eigen::Index j = 0; j < nb; ++j) sum += segment_pair_angle(a0, a1, b.row(j), b.row((j + 1) % nb));
  }
  return sum / (4.0 * M_PI);
}

std::vector<std::vector<int>> tunnel_loops(const mesh::TriMesh& T1, const TunnelLoopOptions& o) {
  const int genus = closed_surface_genus(T1.F);
  if (genus < 1) throw bad_input("tunnel loops: the surface has genus 0 (no hole to go round)");
  const SurfaceGraph g = surface_graph(T1);
  const std::size_t nv = g.adjacency.size();
  std::vector<char> mark(nv, 0);
  BasePoints bases(g, 0);
  std::vector<Candidate> candidates = generators_through(T1, g, bases.next(), mark);
  if (static_cast<int>(candidates.size()) != 2 * genus)
    throw internal_error("tunnel loops: " + std::to_string(candidates.size()) + " generators for genus " +
                         std::to_string(genus));
  // Off the surface by a hundredth of an edge: far below any feature the mesh resolves.
  const TunnelSearch search(T1, g, candidates, 1e-2 * g.mean_edge);
  for (int r = 1; r < o.roots && r < static_cast<int>(nv); ++r)
    for (Candidate& c : generators_through(T1, g, bases.next(), mark)) candidates.push_back(std::move(c));
  Chosen chosen = choose_loops(std::move(candidates), search, genus, nv);
  if (static_cast<int>(chosen.loops.size()) < genus)
    throw bad_input("tunnel loops: found " + std::to_string(chosen.loops.size()) + " disjoint loops round the " +
                    std::to_string(genus) + " holes; the surface may be too coarse between them");
  for (int round = 0; round < o.tighten_rounds; ++round) {
    bool moved = false;
    for (std::size_t i = 0; i < chosen.loops.size(); ++i) moved = tighten(T1, g, search, chosen, i) || moved;
    if (!moved) break;
  }
  std::vector<std::vector<int>> loops;
  for (Candidate& c : chosen.loops) loops.push_back(std::move(c.cycle));
  return loops;
}

}  // namespace igaprep::param
