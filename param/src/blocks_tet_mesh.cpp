#include "igaprep/param/blocks_tet_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <tuple>
#include <utility>

#include <Eigen/Geometry>

#include "igaprep/core/error.h"
#include "igaprep/core/point_merger.h"

namespace igaprep::param {

namespace {

// Corners of a sample cell: local index a + 2 b + 4 c for offsets (a, b, c).
int bit(int corner, int axis) { return (corner >> axis) & 1; }

// The cell's corners in the global order: by global index, ties (corners
// merged on a collapsed side) by local index, so the order is strict.
struct CellOrder {
  std::array<int, 8> g;
  bool less(int a, int b) const { return g[a] != g[b] ? g[a] < g[b] : a < b; }
};

// The four corners of the cell face with `axis` fixed at `side`, in cyclic
// order.
std::array<int, 4> face_corners(int axis, int side) {
  const int e1 = (axis + 1) % 3, e2 = (axis + 2) % 3;
  const int base = side << axis;
  return {{base, base | (1 << e1), base | (1 << e1) | (1 << e2), base | (1 << e2)}};
}

// The face's two triangles (local corners): cut along the diagonal through
// its smallest corner, the rule that makes neighbours agree.
std::array<std::array<int, 3>, 2> face_triangles(const CellOrder& order, int axis, int side) {
  const std::array<int, 4> q = face_corners(axis, side);
  int p = 0;
  for (int r = 1; r < 4; ++r)
    if (order.less(q[r], q[p])) p = r;
  const int a = q[p], b = q[(p + 1) % 4], c = q[(p + 2) % 4], d = q[(p + 3) % 4];
  return {{{{a, b, c}}, {{a, c, d}}}};
}

// Orientation of a tet of local corners in the reference cube.
int reference_sign(int a, int b, int c, int d) {
  Eigen::Matrix3d M;
  for (int r = 0; r < 3; ++r) {
    M(r, 0) = bit(b, r) - bit(a, r);
    M(r, 1) = bit(c, r) - bit(a, r);
    M(r, 2) = bit(d, r) - bit(a, r);
  }
  const double det = M.determinant();
  return det > 0 ? 1 : (det < 0 ? -1 : 0);
}

// The six tets of a cell (local corners, positively oriented in the reference
// cube): the cone from its smallest corner over the cut faces not containing
// it (a convex cube is the union of these cones, none flat).
std::array<std::array<int, 4>, 6> cell_tets(const CellOrder& order) {
  int v0 = 0;
  for (int c = 1; c < 8; ++c)
    if (order.less(c, v0)) v0 = c;
  std::array<std::array<int, 4>, 6> out{};
  int n = 0;
  for (int axis = 0; axis < 3; ++axis)
    for (const auto& t : face_triangles(order, axis, 1 - bit(v0, axis))) {
      std::array<int, 4> tet{{v0, t[0], t[1], t[2]}};
      if (reference_sign(tet[0], tet[1], tet[2], tet[3]) < 0) std::swap(tet[2], tet[3]);
      out[n++] = tet;
    }
  return out;
}

struct TetFace {
  std::array<int, 3> key;  // sorted vertex indices
  std::array<int, 3> out;  // oriented outward from the tet
  int tet;
};

}  // namespace

BlocksTetMesh blocks_tet_mesh(const std::vector<SampledBlock>& blocks, double merge_tolerance) {
  if (blocks.empty()) throw bad_input("blocks_tet_mesh: no blocks");
  if (!(merge_tolerance > 0.0) || !std::isfinite(merge_tolerance))
    throw bad_input("blocks_tet_mesh: merge tolerance must be positive and finite, got " + std::to_string(merge_tolerance));
  const Eigen::Index rows0 = blocks[0].samples.rows();
  const int m = static_cast<int>(std::lround(std::cbrt(static_cast<double>(rows0))));
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const Eigen::MatrixXd& S = blocks[b].samples;
    if (S.cols() != 3)
      throw bad_input("blocks_tet_mesh: block " + std::to_string(b) + " has " + std::to_string(S.cols()) +
                      " sample columns (expected 3)");
    if (m < 2 || static_cast<Eigen::Index>(m) * m * m != rows0)
      throw bad_input("blocks_tet_mesh: block 0 has " + std::to_string(rows0) + " samples, not m^3 with m >= 2");
    if (S.rows() != rows0)
      throw bad_input("blocks_tet_mesh: block " + std::to_string(b) + " has " + std::to_string(S.rows()) +
                      " samples, block 0 has " + std::to_string(rows0) + " (all blocks need the same m)");
    if (!S.allFinite()) throw bad_input("blocks_tet_mesh: block " + std::to_string(b) + " has non-finite samples");
  }

  BlocksTetMesh out;
  const int nb = static_cast<int>(blocks.size());
  const auto sample = [m](int i, int j, int k) { return i + m * (j + m * k); };

  // Global vertex indices of every block's samples.
  PointMerger merger(merge_tolerance);
  std::vector<int> owner;  // block that created each vertex
  std::vector<std::vector<int>> gid(blocks.size(), std::vector<int>(static_cast<std::size_t>(rows0)));
  for (int b = 0; b < nb; ++b)
    for (Eigen::Index r = 0; r < rows0; ++r) {
      const auto [v, fresh] = merger.insert(blocks[static_cast<std::size_t>(b)].samples.row(r).transpose());
      gid[static_cast<std::size_t>(b)][static_cast<std::size_t>(r)] = v;
      if (fresh) owner.push_back(b);
      else if (owner[static_cast<std::size_t>(v)] != b) ++out.merged_points;
      else ++out.collapsed_points;
    }
  const auto& P = merger.points();
  out.tets.V.resize(static_cast<Eigen::Index>(P.size()), 3);
  for (std::size_t v = 0; v < P.size(); ++v) out.tets.V.row(static_cast<Eigen::Index>(v)) = P[v].transpose();

  const auto cell_order = [&](int b, int i, int j, int k) {
    CellOrder o;
    for (int c = 0; c < 8; ++c)
      o.g[c] = gid[static_cast<std::size_t>(b)][static_cast<std::size_t>(sample(i + bit(c, 0), j + bit(c, 1), k + bit(c, 2)))];
    return o;
  };

  // Tets.
  std::vector<std::array<int, 4>> T;
  std::vector<int> tet_block;
  T.reserve(blocks.size() * 6 * static_cast<std::size_t>((m - 1) * (m - 1) * (m - 1)));
  for (int b = 0; b < nb; ++b)
    for (int k = 0; k + 1 < m; ++k)
      for (int j = 0; j + 1 < m; ++j)
        for (int i = 0; i + 1 < m; ++i) {
          const CellOrder o = cell_order(b, i, j, k);
          for (const auto& t : cell_tets(o)) {
            const std::array<int, 4> g{{o.g[t[0]], o.g[t[1]], o.g[t[2]], o.g[t[3]]}};
            bool flat = false;
            for (int x = 0; x < 4; ++x)
              for (int y = x + 1; y < 4; ++y) flat = flat || g[x] == g[y];
            if (flat) {  // merged corners of a collapsed side
              ++out.collapsed_tets;
              continue;
            }
            T.push_back(g);
            tet_block.push_back(b);
          }
        }
  const Eigen::Index nt = static_cast<Eigen::Index>(T.size());
  out.tets.T.resize(nt, 4);
  out.block.resize(nt);
  out.material.resize(nt);
  for (Eigen::Index t = 0; t < nt; ++t) {
    const auto& g = T[static_cast<std::size_t>(t)];
    for (int c = 0; c < 4; ++c) out.tets.T(t, c) = g[c];
    out.block[t] = tet_block[static_cast<std::size_t>(t)];
    out.material[t] = blocks[static_cast<std::size_t>(out.block[t])].material;
    const Eigen::Vector3d a = P[g[0]], e1 = P[g[1]] - a, e2 = P[g[2]] - a, e3 = P[g[3]] - a;
    if (e1.cross(e2).dot(e3) <= 0.0) ++out.non_positive_tets;
  }
  out.tets.material = out.material;

  // Every tet face, sorted by its vertex set, to find the tets of a triangle.
  static constexpr int kOutward[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  std::vector<TetFace> faces;
  faces.reserve(static_cast<std::size_t>(4 * nt));
  for (Eigen::Index t = 0; t < nt; ++t)
    for (const auto& f : kOutward) {
      TetFace tf;
      for (int c = 0; c < 3; ++c) tf.out[c] = out.tets.T(t, f[c]);
      tf.key = tf.out;
      std::sort(tf.key.begin(), tf.key.end());
      tf.tet = static_cast<int>(t);
      faces.push_back(tf);
    }
  std::sort(faces.begin(), faces.end(),
            [](const TetFace& x, const TetFace& y) { return std::tie(x.key, x.tet) < std::tie(y.key, y.tet); });
  for (std::size_t f = 0; f < faces.size();) {
    std::size_t e = f;
    while (e < faces.size() && faces[e].key == faces[f].key) ++e;
    if (e - f > 2) ++out.nonmanifold_faces;
    f = e;
  }
  const auto tets_of = [&](const std::array<int, 3>& key) {
    const auto lo = std::lower_bound(faces.begin(), faces.end(), key,
                                     [](const TetFace& x, const std::array<int, 3>& k) { return x.key < k; });
    auto hi = lo;
    while (hi != faces.end() && hi->key == key) ++hi;
    return std::make_pair(lo, hi);
  };

  // Marked faces: the triangles of every block side, cut as its cells cut
  // them, on the model boundary or between materials.
  std::vector<std::array<int, 3>> F;
  std::vector<int> marker;
  for (int b = 0; b < nb; ++b) {
    const SampledBlock& B = blocks[static_cast<std::size_t>(b)];
    for (int s = 0; s < 6; ++s) {
      const int axis = s / 2, side = s % 2;
      for (int y = 0; y + 1 < m; ++y)
        for (int x = 0; x + 1 < m; ++x) {
          // The cell next to the side: the fixed direction at 0 or m - 2.
          std::array<int, 3> ijk{};
          ijk[static_cast<std::size_t>(axis)] = side * (m - 2);
          ijk[static_cast<std::size_t>((axis + 1) % 3)] = x;
          ijk[static_cast<std::size_t>((axis + 2) % 3)] = y;
          const CellOrder o = cell_order(b, ijk[0], ijk[1], ijk[2]);
          for (const auto& t : face_triangles(o, axis, side)) {
            std::array<int, 3> key{{o.g[t[0]], o.g[t[1]], o.g[t[2]]}};
            std::sort(key.begin(), key.end());
            if (key[0] == key[1] || key[1] == key[2]) continue;  // flat: a collapsed side
            const auto [lo, hi] = tets_of(key);
            const auto count = hi - lo;
            if (count == 1) {
              if (B.side_label[static_cast<std::size_t>(s)] >= 0) {
                F.push_back(lo->out);
                marker.push_back(B.side_label[static_cast<std::size_t>(s)]);
              } else {
                ++out.open_faces;
              }
            } else if (count == 2) {
              const int other = out.block[lo->tet] == b ? (lo + 1)->tet : lo->tet;
              const int ob = out.block[other];
              const int ma = B.material, mb = blocks[static_cast<std::size_t>(ob)].material;
              if (ma != mb && b < ob) {  // once, from the lower block
                F.push_back(out.block[lo->tet] == b ? lo->out : (lo + 1)->out);
                marker.push_back(kInterfaceMarker + std::max(ma, mb));
              }
            }
          }
        }
    }
  }
  out.tets.F.resize(static_cast<Eigen::Index>(F.size()), 3);
  out.tets.F_marker.resize(static_cast<Eigen::Index>(F.size()));
  for (std::size_t f = 0; f < F.size(); ++f) {
    for (int c = 0; c < 3; ++c) out.tets.F(static_cast<Eigen::Index>(f), c) = F[f][c];
    out.tets.F_marker[static_cast<Eigen::Index>(f)] = marker[f];
  }
  return out;
}

}  // namespace igaprep::param
