#include "igaprep/param/midsurface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <unordered_map>

#include <Eigen/Geometry>

#include "igaprep/core/edge_key.h"
#include "igaprep/core/error.h"
#include "igaprep/param/gradient.h"
#include "igaprep/param/harmonic_field.h"
#include "igaprep/param/sheet_topology.h"
#include "igaprep/param/stiffness_matrix.h"
#include "igaprep/param/tet_topology.h"
#include "igaprep/param/trace_gradient.h"

namespace igaprep::param {

namespace {

// A tet's six edges as pairs of its corners.
constexpr int kTetEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

}  // namespace

int split_loop_chords(mesh::TetMesh& tets, const CutLoops& cut) {
  const Eigen::Index n1 = cut.surface.V.rows();
  std::vector<char> on_loop(static_cast<std::size_t>(n1), 0);
  std::set<std::uint64_t> loop_edges;
  for (const auto& loop : cut.loops)
    for (std::size_t i = 0; i < loop.size(); ++i) {
      on_loop[static_cast<std::size_t>(loop[i])] = 1;
      const int a = loop[i], b = loop[(i + 1) % loop.size()];
      loop_edges.insert(edge_key(a, b));
    }
  int total = 0;
  for (int pass = 0; pass < 64; ++pass) {
    std::map<std::uint64_t, int> mid;  // edge -> new vertex
    std::vector<char> touched(static_cast<std::size_t>(tets.T.rows()), 0);
    std::map<std::uint64_t, std::vector<int>> edge_tets;
    for (Eigen::Index c = 0; c < tets.T.rows(); ++c)
      for (const auto& e : kTetEdges) {
        const int a = tets.T(c, e[0]), b = tets.T(c, e[1]);
        if (a >= n1 || b >= n1 || !on_loop[a] || !on_loop[b]) continue;
        const std::uint64_t k = edge_key(a, b);
        if (!loop_edges.count(k)) edge_tets[k].push_back(static_cast<int>(c));
      }
    if (edge_tets.empty()) return total;
    std::vector<std::array<int, 4>> extra;
    std::vector<int> extra_material;
    for (const auto& [k, cells] : edge_tets) {
      bool free = true;
      for (int c : cells) free = free && !touched[c];
      if (!free) continue;
      const int a = static_cast<int>(k >> 32), b = static_cast<int>(k & 0xffffffffu);
      const int m = static_cast<int>(tets.V.rows());
      tets.V.conservativeResize(m + 1, 3);
      tets.V.row(m) = 0.5 * (tets.V.row(a) + tets.V.row(b));
      for (int c : cells) {
        touched[c] = 1;
        std::array<int, 4> second{};
        for (int j = 0; j < 4; ++j) second[j] = tets.T(c, j) == a ? m : tets.T(c, j);
        for (int j = 0; j < 4; ++j)
          if (tets.T(c, j) == b) tets.T(c, j) = m;
        extra.push_back(second);
        extra_material.push_back(tets.material(c));
      }
      ++total;
    }
    const Eigen::Index nt = tets.T.rows();
    tets.T.conservativeResize(nt + static_cast<Eigen::Index>(extra.size()), 4);
    tets.material.conservativeResize(nt + static_cast<Eigen::Index>(extra.size()));
    for (std::size_t i = 0; i < extra.size(); ++i) {
      for (int j = 0; j < 4; ++j) tets.T(nt + static_cast<Eigen::Index>(i), j) = extra[i][j];
      tets.material(nt + static_cast<Eigen::Index>(i)) = extra_material[i];
    }
  }
  throw internal_error("midsurface: splitting tet edges between loop vertices did not finish");
}

Eigen::VectorXd midsurface_field(const mesh::TetMesh& tets, const CutLoops& cut) {
  const Eigen::Index n1 = cut.surface.V.rows();
  if (tets.V.rows() < n1 || tets.V.topRows(n1) != cut.surface.V)
    throw bad_input("midsurface: the tet mesh does not start with the vertices of the cut surface T1 "
                    "(tetrahedralize the cut surface, not the original T1)");
  std::vector<std::vector<int>> sets(3);
  for (Eigen::Index i = 0; i < n1; ++i) {
    const int s = cut.vertex_side(i);
    sets[s > 0 ? 0 : (s < 0 ? 1 : 2)].push_back(static_cast<int>(i));
  }
  HarmonicSolver solver(tet_stiffness(tets.V, tets.T), sets);
  return solver.solve({1.0, -1.0, 0.0});
}

namespace {

// The centroid of tet c, for messages.
std::string point_text(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T, int c) {
  const Eigen::RowVector3d p = 0.25 * (V.row(T(c, 0)) + V.row(T(c, 1)) + V.row(T(c, 2)) + V.row(T(c, 3)));
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.4g, %.4g, %.4g", p(0), p(1), p(2));
  return buf;
}

// The tets round an edge between two fixed vertices at 0, ordered as a fan
// from one face on T1 to the other: the vertices opposite the edge, in that
// order (empty when the fan is closed or not one path).
std::vector<int> edge_fan(const Eigen::MatrixXi& T, const std::vector<int>& tets, int a, int b) {
  std::map<int, std::vector<int>> at;  // opposite vertex -> the fan's tets holding it
  std::vector<std::array<int, 2>> opposite;
  for (int c : tets) {
    std::array<int, 2> o{};
    int n = 0;
    for (int k = 0; k < 4; ++k)
      if (T(c, k) != a && T(c, k) != b && n < 2) o[n++] = T(c, k);
    opposite.push_back(o);
    for (int v : o) at[v].push_back(static_cast<int>(opposite.size()) - 1);
  }
  int start = -1;
  for (const auto& [v, list] : at)
    if (list.size() == 1) {
      start = v;
      break;
    }
  if (start < 0) return {};
  std::vector<int> fan{start};
  std::vector<char> used(opposite.size(), 0);
  for (int v = start;;) {
    int next_tet = -1;
    for (int t : at[v])
      if (!used[t]) next_tet = t;
    if (next_tet < 0) break;
    used[next_tet] = 1;
    v = opposite[next_tet][0] == v ? opposite[next_tet][1] : opposite[next_tet][0];
    fan.push_back(v);
  }
  return fan.size() == opposite.size() + 1 ? fan : std::vector<int>{};
}

// Where a discrete harmonic f is not monotone round a loop edge (a free
// vertex next to the loop with the other side's sign, between two of its
// own), the edge would get three triangles of M0. Along each fan of a loop
// edge the signs must change once, from the first T1 face's side to the
// other's; the free vertices that break this at the least total |f| change
// sign. Returns how many did.
int settle_loop_edge_fans(const Eigen::MatrixXi& T, Eigen::Index num_fixed, Eigen::VectorXd& g) {
  auto loop_vertex = [&](int v) { return v < num_fixed && g(v) == 0.0; };
  std::map<std::pair<int, int>, std::vector<int>> edge_tets;
  for (Eigen::Index c = 0; c < T.rows(); ++c)
    for (const auto& e : kTetEdges) {
      int a = T(c, e[0]), b = T(c, e[1]);
      if (!loop_vertex(a) || !loop_vertex(b)) continue;
      if (a > b) std::swap(a, b);
      edge_tets[{a, b}].push_back(static_cast<int>(c));
    }
  int changed = 0;
  for (const auto& [edge, tets] : edge_tets) {
    const std::vector<int> fan = edge_fan(T, tets, edge.first, edge.second);
    if (fan.size() < 3) continue;
    const double first = g(fan.front()), last = g(fan.back());
    if (!(first * last < 0.0)) continue;  // not a loop edge between the two sides
    // Cost of the change after fan[j - 1]: the free vertices on the wrong side.
    auto wrong = [&](std::size_t i, std::size_t j) { return (i < j ? first : last) * g(fan[i]) < 0.0; };
    std::size_t best_j = 1;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t j = 1; j < fan.size(); ++j) {
      double cost = 0.0;
      for (std::size_t i = 1; i + 1 < fan.size(); ++i)
        if (wrong(i, j)) cost += fan[i] < num_fixed ? std::numeric_limits<double>::infinity() : std::abs(g(fan[i]));
      if (cost < best) best = cost, best_j = j;
    }
    if (!std::isfinite(best)) continue;
    for (std::size_t i = 1; i + 1 < fan.size(); ++i)
      if (wrong(i, best_j)) g(fan[i]) = -g(fan[i]), ++changed;
  }
  return changed;
}

}  // namespace

Midsurface zero_sheet(const mesh::TetMesh& tets, const Eigen::VectorXd& f, Eigen::Index num_fixed, double snap) {
  const Eigen::MatrixXd& V = tets.V;
  const Eigen::MatrixXi& T = tets.T;
  Midsurface out;
  Eigen::VectorXd g = f;
  // Snap free vertices that would give slivers (an edge cut within `snap` of them).
  std::vector<char> to_zero(static_cast<std::size_t>(V.rows()), 0);
  for (Eigen::Index c = 0; c < T.rows(); ++c)
    for (const auto& e : kTetEdges) {
      const int a = T(c, e[0]), b = T(c, e[1]);
      if (!(f(a) * f(b) < 0.0)) continue;
      const double t = f(a) / (f(a) - f(b));
      if (t < snap && a >= num_fixed) to_zero[a] = 1;
      if (t > 1.0 - snap && b >= num_fixed) to_zero[b] = 1;
    }
  for (Eigen::Index i = num_fixed; i < V.rows(); ++i)
    if (to_zero[i] || std::abs(g(i)) < 1e-14) {
      if (g(i) != 0.0) ++out.snapped;
      g(i) = 0.0;
    }
  // A flip can break another fan that shares the vertex: a few rounds.
  for (int round = 0; round < 3; ++round) {
    const int n = settle_loop_edge_fans(T, num_fixed, g);
    out.settled += n;
    if (n == 0) break;
  }

  std::unordered_map<std::uint64_t, int> vid;
  std::vector<std::array<int, 2>> edges;
  std::vector<double> ts;
  auto vertex = [&](int a, int b) {  // a == b: the tet vertex itself (at 0)
    if (a > b) std::swap(a, b);
    const std::uint64_t k = edge_key(a, b);
    auto it = vid.find(k);
    if (it != vid.end()) return it->second;
    const double t = a == b ? 0.0 : g(a) / (g(a) - g(b));
    edges.push_back({a, b});
    ts.push_back(t);
    const int id = static_cast<int>(edges.size()) - 1;
    vid[k] = id;
    return id;
  };
  std::vector<std::array<int, 3>> tris;
  std::vector<int> tri_tet;
  auto emit = [&](int c, std::array<int, 3> tri, const Eigen::Vector3d& grad) {
    auto pos = [&](int id) {
      const auto& e = edges[static_cast<std::size_t>(id)];
      return Eigen::Vector3d((1.0 - ts[id]) * V.row(e[0]) + ts[id] * V.row(e[1]));
    };
    const Eigen::Vector3d n = (pos(tri[1]) - pos(tri[0])).cross(pos(tri[2]) - pos(tri[0]));
    if (n.dot(grad) < 0.0) std::swap(tri[1], tri[2]);
    tris.push_back(tri);
    tri_tet.push_back(c);
  };
  struct ZeroFace {
    std::array<int, 3> v;
    int tet;
    int sign;
  };
  std::map<std::array<int, 3>, std::vector<ZeroFace>> zero_faces;
  for (Eigen::Index ci = 0; ci < T.rows(); ++ci) {
    const int c = static_cast<int>(ci);
    std::vector<int> P, N, Z;
    for (int k = 0; k < 4; ++k) {
      const int v = T(c, k);
      (g(v) > 0.0 ? P : (g(v) < 0.0 ? N : Z)).push_back(v);
    }
    if (Z.size() == 4)
      throw bad_input("all four vertices of tet " + std::to_string(c) + " (near (" + point_text(V, T, c) +
                      ")) are at f = 0: the cut loops run closer together there than a tet is wide");
    if (P.empty() && N.empty()) continue;
    if ((P.empty() || N.empty()) && Z.size() != 3) continue;  // touches f = 0 in a vertex or an edge at most
    Eigen::Matrix<double, 4, 3> gp;
    tet_barycentric_gradients(V.row(T(c, 0)), V.row(T(c, 1)), V.row(T(c, 2)), V.row(T(c, 3)), gp);
    Eigen::Vector3d grad = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) grad += g(T(c, k)) * gp.row(k).transpose();
    if (Z.size() == 3) {
      std::array<int, 3> key{Z[0], Z[1], Z[2]};
      std::sort(key.begin(), key.end());
      zero_faces[key].push_back({{Z[0], Z[1], Z[2]}, c, P.empty() ? -1 : 1});
      continue;
    }
    if (Z.empty()) {
      if (P.size() == 1 || N.size() == 1) {
        const int lone = P.size() == 1 ? P[0] : N[0];
        const std::vector<int>& rest = P.size() == 1 ? N : P;
        emit(c, {vertex(lone, rest[0]), vertex(lone, rest[1]), vertex(lone, rest[2])}, grad);
      } else {
        const int q0 = vertex(N[0], P[0]), q1 = vertex(N[0], P[1]), q2 = vertex(N[1], P[1]), q3 = vertex(N[1], P[0]);
        emit(c, {q0, q1, q2}, grad);
        emit(c, {q0, q2, q3}, grad);
      }
    } else if (Z.size() == 1) {
      const int z = vertex(Z[0], Z[0]);
      if (P.size() == 2) emit(c, {z, vertex(N[0], P[0]), vertex(N[0], P[1])}, grad);
      else emit(c, {z, vertex(P[0], N[0]), vertex(P[0], N[1])}, grad);
    } else {  // two zeros, one +, one -
      emit(c, {vertex(Z[0], Z[0]), vertex(Z[1], Z[1]), vertex(N[0], P[0])}, grad);
    }
  }
  // A tet face at 0: part of the sheet when the tets on its two sides lie on opposite sides.
  for (const auto& [key, list] : zero_faces) {
    if (list.size() != 2 || list[0].sign == list[1].sign) continue;
    const ZeroFace& lo = list[0].sign < 0 ? list[0] : list[1];
    const int c = lo.tet;
    Eigen::Matrix<double, 4, 3> gp;
    tet_barycentric_gradients(V.row(T(c, 0)), V.row(T(c, 1)), V.row(T(c, 2)), V.row(T(c, 3)), gp);
    Eigen::Vector3d grad = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) grad += g(T(c, k)) * gp.row(k).transpose();
    emit(c, {vertex(lo.v[0], lo.v[0]), vertex(lo.v[1], lo.v[1]), vertex(lo.v[2], lo.v[2])}, grad);
  }

  const Eigen::Index nv = static_cast<Eigen::Index>(edges.size());
  out.mesh.V.resize(nv, 3);
  out.edge.resize(nv, 2);
  out.t.resize(nv);
  for (Eigen::Index i = 0; i < nv; ++i) {
    const auto& e = edges[static_cast<std::size_t>(i)];
    out.edge(i, 0) = e[0];
    out.edge(i, 1) = e[1];
    out.t(i) = ts[static_cast<std::size_t>(i)];
    out.mesh.V.row(i) = e[0] == e[1] ? Eigen::RowVector3d(V.row(e[0])) : Eigen::RowVector3d((1.0 - out.t(i)) * V.row(e[0]) + out.t(i) * V.row(e[1]));
  }
  out.mesh.F.resize(static_cast<Eigen::Index>(tris.size()), 3);
  out.tet.resize(static_cast<Eigen::Index>(tris.size()));
  for (std::size_t i = 0; i < tris.size(); ++i) {
    for (int k = 0; k < 3; ++k) out.mesh.F(static_cast<Eigen::Index>(i), k) = tris[i][k];
    out.tet(static_cast<Eigen::Index>(i)) = tri_tet[i];
  }
  out.field = g;
  return out;
}

Midsurface extract_midsurface(const mesh::TetMesh& tets, const CutLoops& cut, const Eigen::VectorXd& f, double snap) {
  const Eigen::Index n1 = cut.surface.V.rows();
  const int wanted = cut.genus + 1;
  std::string problem;
  for (double s : {snap, 0.0}) {
    Midsurface m;
    try {
      m = zero_sheet(tets, f, n1, s);
    } catch (const Error& e) {  // snapping can put a whole tet at 0: try without it
      if (e.kind() != ErrorKind::BadInput) throw;
      problem = std::string("the midsurface M0: ") + e.what();
      if (s == 0.0) break;
      continue;
    }
    const SheetTopology topo = analyze_sheet(m.mesh.F, m.mesh.V.rows());
    problem = describe_sheet_problem(topo, wanted, "the midsurface M0");
    if (problem.empty()) {
      // Its boundary must be the cut loops: every boundary vertex a T1 vertex at 0.
      for (const auto& loop : topo.boundary_loops)
        for (int v : loop)
          if (m.edge(v, 0) != m.edge(v, 1) || m.edge(v, 0) >= n1) {
            problem = "the midsurface M0 has a boundary vertex (" + std::to_string(v) + ") off the cut loops";
            break;
          }
    }
    if (problem.empty()) {
      m.boundary_loops = topo.boundary_loops;
      return m;
    }
    if (s == 0.0) break;
  }
  throw bad_input(problem + " (cut: " + cut.source +
                  "); the cut loops must bound one sheet through the solid: give another plane or loops ('midsurface.cut'), "
                  "or a finer tet mesh ('tetmesh.max_volume') where they run closer together than a tet is wide");
}

PathLengthStats midsurface_path_lengths(const mesh::TetMesh& tets, const Eigen::VectorXd& f, const CutLoops& cut) {
  PathLengthStats st;
  const TetTopology topo = build_tet_topology(tets.T, tets.V.rows());
  GradientTracer tracer(tets.V, tets.T, topo, f);
  TraceTarget target;
  target.use_iso = true;
  target.iso = 0.0;
  std::vector<double> lengths;
  for (Eigen::Index v = 0; v < cut.surface.V.rows(); ++v) {
    const int s = cut.vertex_side(v);
    if (s == 0) continue;
    const int start = topo.vertex_cells_start[v];
    if (start == topo.vertex_cells_start[v + 1]) continue;
    const int c = topo.vertex_cells[start];
    Eigen::Vector4d bary = Eigen::Vector4d::Zero();
    for (int k = 0; k < 4; ++k)
      if (tets.T(c, k) == v) bary(k) = 1.0;
    TraceOptions opt;
    opt.descend = s > 0;
    opt.max_steps = 100000;
    ++st.traced;
    const TraceResult r = tracer.trace(c, bary, target, opt);
    if (r.status != TraceStatus::Reached) continue;
    double len = 0.0;
    for (Eigen::Index i = 1; i < r.path.rows(); ++i) len += (r.path.row(i) - r.path.row(i - 1)).norm();
    lengths.push_back(len);
  }
  st.reached = static_cast<int>(lengths.size());
  if (lengths.empty()) return st;
  double sum = 0.0;
  for (double l : lengths) sum += l;
  st.mean = sum / static_cast<double>(lengths.size());
  double var = 0.0;
  for (double l : lengths) var += (l - st.mean) * (l - st.mean);
  st.variance = var / static_cast<double>(lengths.size());
  st.min = *std::min_element(lengths.begin(), lengths.end());
  st.max = *std::max_element(lengths.begin(), lengths.end());
  return st;
}

}  // namespace igaprep::param
