// Marching tetrahedra with one output vertex per cut edge. A vertex whose
// value equals `iso` counts as above (field >= iso): the surface is that of
// the field lowered by an infinitesimal amount, so it stays a manifold; such
// a vertex gives output points with t = 0 or 1 that coincide with it.
// Orientation is decided combinatorially from the parity of the vertex order
// in the positively oriented tet, so it never depends on round-off.
#include "igaprep/mesh/marching_tets.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "igaprep/core/error.h"

namespace igaprep::mesh {
namespace {

// Parity of a permutation of 4 distinct values (true = even).
bool even_permutation(std::array<int, 4> p) {
  int inversions = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if (p[i] > p[j]) ++inversions;
  return inversions % 2 == 0;
}

}  // namespace

IsoSurface marching_tets(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T, const Eigen::VectorXd& field,
                         double iso) {
  if (V.cols() != 3) throw bad_input("marching_tets: V must have 3 columns");
  if (T.rows() > 0 && T.cols() != 4) throw bad_input("marching_tets: T must have 4 columns");
  if (field.size() != V.rows()) {
    throw bad_input("marching_tets: field has " + std::to_string(field.size()) + " values for " +
                    std::to_string(V.rows()) + " vertices");
  }
  if (T.size() > 0 && (T.minCoeff() < 0 || T.maxCoeff() >= V.rows())) {
    throw bad_input("marching_tets: T has an out-of-range vertex index");
  }
  for (Eigen::Index i = 0; i < field.size(); ++i) {
    if (!std::isfinite(field(i))) throw bad_input("marching_tets: field value at vertex " + std::to_string(i) + " is not finite");
  }

  std::unordered_map<std::uint64_t, int> edge_vertex;
  std::vector<std::array<int, 2>> edges;
  std::vector<double> ts;
  std::vector<std::array<int, 3>> tris;
  std::vector<int> tri_tet;
  const std::uint64_t nv = static_cast<std::uint64_t>(V.rows());

  // Output vertex on the edge between a below vertex and an above vertex.
  auto cut = [&](int a, int b) {
    const int lo = std::min(a, b), hi = std::max(a, b);
    const std::uint64_t key = static_cast<std::uint64_t>(lo) * nv + static_cast<std::uint64_t>(hi);
    auto it = edge_vertex.find(key);
    if (it != edge_vertex.end()) return it->second;
    const int id = static_cast<int>(edges.size());
    edge_vertex.emplace(key, id);
    edges.push_back({lo, hi});
    // The edge has one value < iso and one >= iso, so the denominator is nonzero.
    ts.push_back((iso - field(lo)) / (field(hi) - field(lo)));
    return id;
  };
  auto add = [&](int a, int b, int c, int tet) {
    tris.push_back({a, b, c});
    tri_tet.push_back(tet);
  };

  for (Eigen::Index t = 0; t < T.rows(); ++t) {
    std::array<int, 4> above, below;
    int na = 0, nb = 0;
    for (int j = 0; j < 4; ++j) {
      const int v = T(t, j);
      if (field(v) >= iso) above[na++] = j; else below[nb++] = j;
    }
    if (na == 0 || nb == 0) continue;
    const int tet = static_cast<int>(t);
    if (na == 1 || nb == 1) {
      // Lone corner `a`; others b, c, d ordered so that (b, c, d, a) is an even
      // permutation of the tet's corners: the triangle (ba, ca, da) then has
      // its normal towards `a`.
      const bool lone_above = (na == 1);
      const int a = lone_above ? above[0] : below[0];
      std::array<int, 3> o;
      const std::array<int, 4>& rest = lone_above ? below : above;
      for (int j = 0; j < 3; ++j) o[j] = rest[j];
      if (!even_permutation({o[0], o[1], o[2], a})) std::swap(o[0], o[1]);
      const int va = T(t, a);
      const int p0 = cut(T(t, o[0]), va), p1 = cut(T(t, o[1]), va), p2 = cut(T(t, o[2]), va);
      if (lone_above) add(p0, p1, p2, tet); else add(p0, p2, p1, tet);
    } else {
      // Below c, d; above a, b with (c, d, a, b) even: the quad
      // (ca, cb, db, da) has its normal towards a and b.
      int c = below[0], d = below[1], a = above[0], b = above[1];
      if (!even_permutation({c, d, a, b})) std::swap(a, b);
      const int ca = cut(T(t, c), T(t, a)), cb = cut(T(t, c), T(t, b)), db = cut(T(t, d), T(t, b)),
                da = cut(T(t, d), T(t, a));
      add(ca, cb, db, tet);
      add(ca, db, da, tet);
    }
  }

  IsoSurface out;
  const int m = static_cast<int>(edges.size());
  out.mesh.V.resize(m, 3);
  out.edge.resize(m, 2);
  out.t.resize(m);
  for (int i = 0; i < m; ++i) {
    out.edge(i, 0) = edges[i][0];
    out.edge(i, 1) = edges[i][1];
    out.t(i) = ts[i];
    out.mesh.V.row(i) = (1.0 - ts[i]) * V.row(edges[i][0]) + ts[i] * V.row(edges[i][1]);
  }
  out.mesh.F.resize(static_cast<Eigen::Index>(tris.size()), 3);
  out.tet.resize(static_cast<Eigen::Index>(tris.size()));
  for (std::size_t f = 0; f < tris.size(); ++f) {
    for (int c = 0; c < 3; ++c) out.mesh.F(f, c) = tris[f][c];
    out.tet(f) = tri_tet[f];
  }
  return out;
}

}  // namespace igaprep::mesh
