#include "igaprep/param/polycube_2d.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include <Eigen/Geometry>
#include <Eigen/Eigenvalues>
#include <Eigen/SparseLU>

#include "igaprep/core/angle.h"
#include "igaprep/core/edge_key.h"
#include "igaprep/core/error.h"
#include "igaprep/param/harmonic_field.h"
#include "igaprep/param/sheet_lobes.h"
#include "edge_graph.h"
#include "polycube_hole_cuts.h"
#include "igaprep/param/stiffness_matrix.h"

namespace igaprep::param {
namespace {

Eigen::Vector3d P(const mesh::TriMesh& m, int i) { return m.V.row(i).transpose(); }

double face_area(const mesh::TriMesh& m, Eigen::Index f) {
  return 0.5 * (P(m, m.F(f, 1)) - P(m, m.F(f, 0))).cross(P(m, m.F(f, 2)) - P(m, m.F(f, 0))).norm();
}

// Expected chord direction of each side when walking the loop (sheet on the left).
Eigen::Vector2d side_direction(DomainSide s, bool outer) {
  const double sg = outer ? 1.0 : -1.0;
  switch (s) {
    case DomainSide::Bottom: return {sg, 0.0};
    case DomainSide::Right: return {0.0, sg};
    case DomainSide::Top: return {-sg, 0.0};
    case DomainSide::Left: return {0.0, -sg};
  }
  return {0.0, 0.0};
}

// Order of sides along a loop: outer B R T L (counter-clockwise), holes B L T R.
std::array<DomainSide, 4> side_order(bool outer) {
  if (outer) return {DomainSide::Bottom, DomainSide::Right, DomainSide::Top, DomainSide::Left};
  return {DomainSide::Bottom, DomainSide::Left, DomainSide::Top, DomainSide::Right};
}

double signed_area(const mesh::TriMesh& m, const std::vector<int>& loop, const SheetFrame& fr) {
  double a = 0.0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Eigen::Vector3d p = P(m, loop[i]) - fr.origin, q = P(m, loop[(i + 1) % loop.size()]) - fr.origin;
    a += 0.5 * (p.dot(fr.e1) * q.dot(fr.e2) - q.dot(fr.e1) * p.dot(fr.e2));
  }
  return a;
}

std::vector<double> arc_lengths(const mesh::TriMesh& m, const std::vector<int>& loop) {
  std::vector<double> s(loop.size() + 1, 0.0);
  for (std::size_t i = 0; i < loop.size(); ++i) s[i + 1] = s[i] + (P(m, loop[(i + 1) % loop.size()]) - P(m, loop[i])).norm();
  return s;
}

// Arc lengths along a loop with each masked run (a lobe's boundary) counted
// as the straight line across its neck: the length the loop keeps on the
// rectangle once the lobes are arms. Without a mask, arc_lengths.
std::vector<double> arc_lengths_across_necks(const mesh::TriMesh& m, const std::vector<int>& loop,
                                             const std::vector<char>& masked) {
  const std::size_t n = loop.size();
  const auto unmasked = std::find(masked.begin(), masked.end(), 0);
  if (unmasked == masked.end()) return arc_lengths(m, loop);
  std::vector<double> edge(n, 0.0);  // edge i runs from position i to i + 1
  const std::size_t u = static_cast<std::size_t>(unmasked - masked.begin());
  std::size_t run_start = u;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = (u + k) % n, j = (i + 1) % n;
    if (masked[j] && !masked[i]) run_start = j;
    const bool inside = masked[i] && masked[j];
    const bool run_ends = inside && !masked[(j + 1) % n];
    if (!inside) edge[i] = (P(m, loop[j]) - P(m, loop[i])).norm();
    else if (run_ends) edge[i] = (P(m, loop[j]) - P(m, loop[run_start])).norm();
  }
  std::vector<double> s(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) s[i + 1] = s[i] + edge[i];
  return s;
}

// Rotates the loop's sides so segment chords follow the expected directions best.
void assign_sides(const mesh::TriMesh& m, PolycubeLoop& L, const SheetFrame& fr) {
  std::array<Eigen::Vector2d, 4> chord;
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector3d d = P(m, L.vertices[L.corners[(k + 1) % 4]]) - P(m, L.vertices[L.corners[k]]);
    chord[k] = Eigen::Vector2d(d.dot(fr.e1), d.dot(fr.e2));
  }
  const auto order = side_order(L.outer);
  int best = 0;
  double best_score = -1e300;
  for (int r = 0; r < 4; ++r) {
    double score = 0.0;
    for (int k = 0; k < 4; ++k) score += chord[k].dot(side_direction(order[(k + r) % 4], L.outer));
    if (score > best_score) {
      best_score = score;
      best = r;
    }
  }
  for (int k = 0; k < 4; ++k) L.sides[k] = order[(k + best) % 4];
}

std::vector<PolycubeLoop> make_loops(const mesh::TriMesh& m, const std::vector<std::vector<int>>& loops,
                                     const SheetFrame& fr) {
  if (loops.empty()) throw bad_input("polycube: the sheet has no boundary loop");
  std::vector<PolycubeLoop> out(loops.size());
  int outer = 0;
  double best = -1e300;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    out[l].vertices = loops[l];
    if (loops[l].size() < 4) throw bad_input("polycube: boundary loop " + std::to_string(l) + " has fewer than 4 vertices");
    const double a = signed_area(m, loops[l], fr);
    if (a > best) {
      best = a;
      outer = static_cast<int>(l);
    }
  }
  out[static_cast<std::size_t>(outer)].outer = true;
  return out;
}

// Corner positions valid: increasing, each segment at least `min_frac` of the loop and 2 edges.
bool corners_ok(const std::vector<double>& s, std::array<int, 4> c, std::size_t n, double min_frac) {
  const double total = s.back();
  for (int k = 0; k < 4; ++k) {
    const int a = c[k], b = c[(k + 1) % 4];
    const int edges = (b - a + static_cast<int>(n)) % static_cast<int>(n);
    const double len = k < 3 ? s[b] - s[a] : total - s[a] + s[b];
    if (edges < 2 || len < min_frac * total) return false;
  }
  return true;
}

// Appends the vertices a split created and replaces the faces by the split ones.
void append_split(mesh::TriMesh& m, const std::vector<Eigen::RowVector3d>& newV,
                  const std::vector<std::array<int, 3>>& faces) {
  const Eigen::Index nv = m.V.rows();
  m.V.conservativeResize(nv + static_cast<Eigen::Index>(newV.size()), 3);
  for (std::size_t i = 0; i < newV.size(); ++i) m.V.row(nv + static_cast<Eigen::Index>(i)) = newV[i];
  m.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (int k = 0; k < 3; ++k) m.F(static_cast<Eigen::Index>(f), k) = faces[f][k];
}

// The faces of m with each split by the midpoints on its edges (1, 2 or 3
// of them; `mid`: edge key -> the midpoint's vertex index). Every new
// triangle holds a midpoint, unless its face had none.
std::vector<std::array<int, 3>> faces_split_at(const mesh::TriMesh& m, const std::map<std::uint64_t, int>& mid) {
  std::vector<std::array<int, 3>> faces;
  for (int f = 0; f < m.F.rows(); ++f) {
    std::array<int, 3> v{m.F(f, 0), m.F(f, 1), m.F(f, 2)}, e{};
    int count = 0;
    for (int j = 0; j < 3; ++j) {
      auto it = mid.find(edge_key(v[j], v[(j + 1) % 3]));
      e[j] = it == mid.end() ? -1 : it->second;
      count += e[j] >= 0;
    }
    if (count == 0) {
      faces.push_back(v);
    } else if (count == 3) {
      faces.push_back({v[0], e[0], e[2]});
      faces.push_back({e[0], v[1], e[1]});
      faces.push_back({e[2], e[1], v[2]});
      faces.push_back({e[0], e[1], e[2]});
    } else if (count == 1) {
      const int j = e[0] >= 0 ? 0 : (e[1] >= 0 ? 1 : 2);
      faces.push_back({v[j], e[j], v[(j + 2) % 3]});
      faces.push_back({e[j], v[(j + 1) % 3], v[(j + 2) % 3]});
    } else {  // two: j is the edge without a midpoint
      const int j = e[0] < 0 ? 0 : (e[1] < 0 ? 1 : 2);
      const int a = v[j], b = v[(j + 1) % 3], c = v[(j + 2) % 3];
      const int mbc = e[(j + 1) % 3], mca = e[(j + 2) % 3];
      faces.push_back({a, b, mbc});
      faces.push_back({a, mbc, mca});
      faces.push_back({mca, mbc, c});
    }
  }
  return faces;
}

}  // namespace

const char* to_string(DomainSide side) {
  switch (side) {
    case DomainSide::Bottom: return "bottom";
    case DomainSide::Right: return "right";
    case DomainSide::Top: return "top";
    case DomainSide::Left: return "left";
  }
  return "?";
}

SheetFrame sheet_frame(const mesh::TriMesh& m) {
  SheetFrame fr;
  double area = 0.0;
  Eigen::Vector3d c = Eigen::Vector3d::Zero(), n = Eigen::Vector3d::Zero();
  for (int f = 0; f < m.F.rows(); ++f) {
    const Eigen::Vector3d a = P(m, m.F(f, 0)), b = P(m, m.F(f, 1)), d = P(m, m.F(f, 2));
    const Eigen::Vector3d cr = (b - a).cross(d - a);
    area += 0.5 * cr.norm();
    c += 0.5 * cr.norm() * (a + b + d) / 3.0;
    n += cr;
  }
  if (!(area > 0.0) || !(n.norm() > 0.0)) throw bad_input("polycube: the sheet has no area");
  c /= area;
  n.normalize();
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  for (int f = 0; f < m.F.rows(); ++f) {
    const Eigen::Vector3d a = P(m, m.F(f, 0)), b = P(m, m.F(f, 1)), d = P(m, m.F(f, 2));
    const double A = 0.5 * (b - a).cross(d - a).norm();
    for (const Eigen::Vector3d& x : {a, b, d}) C += (A / 3.0) * (x - c) * (x - c).transpose();
  }
  const Eigen::Matrix3d Pn = Eigen::Matrix3d::Identity() - n * n.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(Pn * C * Pn);
  Eigen::Vector3d e1 = Pn * eig.eigenvectors().col(2);
  if (!(e1.norm() > 1e-12)) e1 = Pn * Eigen::Vector3d::UnitX();
  if (!(e1.norm() > 1e-12)) e1 = Pn * Eigen::Vector3d::UnitY();
  e1.normalize();
  Eigen::Index i;
  e1.cwiseAbs().maxCoeff(&i);
  if (e1(i) < 0) e1 = -e1;  // deterministic sign
  fr.origin = c;
  fr.normal = n;
  fr.e1 = e1;
  fr.e2 = n.cross(e1).normalized();
  return fr;
}

int split_boundary_ears(mesh::TriMesh& m) {
  int total = 0;
  for (int pass = 0; pass < 32; ++pass) {
    std::unordered_map<std::uint64_t, std::vector<int>> ef;
    for (int f = 0; f < m.F.rows(); ++f)
      for (int k = 0; k < 3; ++k) ef[edge_key(m.F(f, k), m.F(f, (k + 1) % 3))].push_back(f);
    std::vector<char> touched(static_cast<std::size_t>(m.F.rows()), 0);
    std::map<std::uint64_t, int> mid;
    std::vector<Eigen::RowVector3d> newV;
    std::vector<char> on_boundary(static_cast<std::size_t>(m.V.rows()), 0);
    for (const auto& [key, fs] : ef)
      if (fs.size() == 1) on_boundary[key >> 32] = on_boundary[key & 0xffffffffu] = 1;
    std::vector<std::uint64_t> keys;
    for (const auto& [key, fs] : ef) keys.push_back(key);
    std::sort(keys.begin(), keys.end());
    for (std::uint64_t key : keys) {
      const auto& fs = ef[key];
      const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
      if (fs.size() != 2 || !on_boundary[a] || !on_boundary[b] || touched[fs[0]] || touched[fs[1]]) continue;
      touched[fs[0]] = touched[fs[1]] = 1;
      mid[key] = static_cast<int>(m.V.rows() + static_cast<Eigen::Index>(newV.size()));
      newV.push_back(0.5 * (m.V.row(a) + m.V.row(b)));
    }
    if (newV.empty()) return total;
    total += static_cast<int>(newV.size());
    append_split(m, newV, faces_split_at(m, mid));  // one midpoint per face at most (touched)
  }
  return total;
}

namespace {

// Arc length along a loop from position a forward to position b.
double arc_between(const std::vector<double>& s, int a, int b) {
  return a <= b ? s[static_cast<std::size_t>(b)] - s[static_cast<std::size_t>(a)]
                : s.back() - s[static_cast<std::size_t>(a)] + s[static_cast<std::size_t>(b)];
}

// Loop positions on a lobe's boundary, its two ends included.
std::vector<char> lobe_mask(std::size_t n, const std::vector<SheetLobe>& lobes) {
  std::vector<char> on(n, 0);
  for (const SheetLobe& l : lobes)
    for (std::size_t p = static_cast<std::size_t>(l.start);; p = (p + 1) % n) {
      on[p] = 1;
      if (p == static_cast<std::size_t>(l.end)) break;
    }
  return on;
}

// Four corners of L outside the masked positions: the extreme points along
// the frame's diagonals. Returns false (corners evenly spread by arc length
// instead, or none) when those are not four in order with long enough
// segments (measured with the lobes across their necks).
bool place_corners(const mesh::TriMesh& m, PolycubeLoop& L, const SheetFrame& fr, const std::vector<char>& masked) {
  const std::size_t n = L.vertices.size();
  // The sides' lengths as the rectangle will have them, lobes across their necks.
  const std::vector<double> s = arc_lengths_across_necks(m, L.vertices, masked);
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  int count = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (!masked[i]) c += P(m, L.vertices[i]), ++count;
  c /= static_cast<double>(std::max(count, 1));
  // The starts of the segments in loop order: outer BL, BR, TR, TL; holes BR, BL, TL, TR.
  const std::array<Eigen::Vector2d, 4> dirs =
      L.outer ? std::array<Eigen::Vector2d, 4>{Eigen::Vector2d(-1, -1), Eigen::Vector2d(1, -1), Eigen::Vector2d(1, 1),
                                               Eigen::Vector2d(-1, 1)}
              : std::array<Eigen::Vector2d, 4>{Eigen::Vector2d(1, -1), Eigen::Vector2d(-1, -1), Eigen::Vector2d(-1, 1),
                                               Eigen::Vector2d(1, 1)};
  std::array<int, 4> pos{};
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector3d d = dirs[k](0) * fr.e1 + dirs[k](1) * fr.e2;
    double best = -1e300;
    for (std::size_t i = 0; i < n; ++i) {
      if (masked[i]) continue;
      const double x = d.dot(P(m, L.vertices[i]) - c);
      if (x > best + 1e-12) {
        best = x;
        pos[k] = static_cast<int>(i);
      }
    }
  }
  // Rotate so that the first corner has the smallest position, then require increasing order.
  const int first = static_cast<int>(std::min_element(pos.begin(), pos.end()) - pos.begin());
  std::array<int, 4> rot{};
  for (int k = 0; k < 4; ++k) rot[k] = pos[(first + k) % 4];
  const bool increasing = rot[0] < rot[1] && rot[1] < rot[2] && rot[2] < rot[3];
  // A long sheet (a blade, a propeller) keeps its corners at its narrow ends
  // even when the end segments are short.
  Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
  for (std::size_t i = 0; i < n; ++i) {
    if (masked[i]) continue;
    const Eigen::Vector2d q(fr.e1.dot(P(m, L.vertices[i]) - c), fr.e2.dot(P(m, L.vertices[i]) - c));
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  const bool elongated = hi(0) - lo(0) > 3.0 * (hi(1) - lo(1));
  if (increasing && (corners_ok(s, rot, n, 0.05) || (elongated && corners_ok(s, rot, n, 0.01)))) {
    L.corners = rot;
    assign_sides(m, L, fr);
    return true;
  }
  if (std::find(masked.begin(), masked.end(), 1) != masked.end()) return false;
  // Evenly by arc length from the first extreme point.
  const double total = s.back();
  const double s0 = s[static_cast<std::size_t>(pos[0])];
  std::array<int, 4> even{};
  for (int k = 0; k < 4; ++k) {
    const double target = std::fmod(s0 + k * total / 4.0, total);
    std::size_t bi = 0;
    double bd = 1e300;
    for (std::size_t i = 0; i < n; ++i) {
      const double d = std::min(std::abs(s[i] - target), total - std::abs(s[i] - target));
      if (d < bd) {
        bd = d;
        bi = i;
      }
    }
    even[k] = static_cast<int>(bi);
  }
  std::sort(even.begin(), even.end());
  if (!corners_ok(s, even, n, 0.0))
    throw bad_input("polycube: boundary loop with " + std::to_string(n) + " vertices is too short for four corners");
  L.corners = even;
  assign_sides(m, L, fr);
  return false;
}

// Each lobe as an arm: its length how far the lobe reaches from its neck's
// middle, its width the lobe's area over that (at least the neck), its tip
// corners splitting the lobe's boundary as side, tip, side in proportion to
// length, width, length. A lobe whose pieces would have fewer than two edges
// gets no arm.
std::vector<LoopArm> loop_arms(const mesh::TriMesh& m, const PolycubeLoop& L, const std::vector<SheetLobe>& lobes) {
  const std::size_t n = L.vertices.size();
  const std::vector<double> s = arc_lengths(m, L.vertices);
  auto edges = [&](int a, int b) { return (b - a + static_cast<int>(n)) % static_cast<int>(n); };
  std::vector<LoopArm> out;
  for (const SheetLobe& lobe : lobes) {
    const Eigen::Vector3d neck_mid = 0.5 * (P(m, L.vertices[lobe.start]) + P(m, L.vertices[lobe.end]));
    LoopArm arm;
    for (std::size_t p = static_cast<std::size_t>(lobe.start); p != static_cast<std::size_t>(lobe.end); p = (p + 1) % n)
      arm.length = std::max(arm.length, (P(m, L.vertices[p]) - neck_mid).norm());
    if (!(arm.length > 0.0)) continue;
    arm.width = std::max(lobe.neck, lobe.area / arm.length);
    const double arc = arc_between(s, lobe.start, lobe.end);
    const double tip = arc * arm.width / (2.0 * arm.length + arm.width);
    arm.corners = {lobe.start, lobe.start, lobe.start, lobe.end};
    for (int k : {1, 2}) {
      const double target = k == 1 ? 0.5 * (arc - tip) : 0.5 * (arc + tip);
      double best = 1e300;
      for (std::size_t p = static_cast<std::size_t>(lobe.start); p != static_cast<std::size_t>(lobe.end); p = (p + 1) % n) {
        const double d = std::abs(arc_between(s, lobe.start, static_cast<int>(p)) - target);
        if (d < best) best = d, arm.corners[static_cast<std::size_t>(k)] = static_cast<int>(p);
      }
    }
    const auto& c = arm.corners;
    if (edges(c[0], c[1]) >= 2 && edges(c[1], c[2]) >= 2 && edges(c[2], c[3]) >= 2 &&
        edges(c[0], c[3]) == edges(c[0], c[1]) + edges(c[1], c[2]) + edges(c[2], c[3]))
      out.push_back(arm);
  }
  // In loop order from corner 0.
  std::sort(out.begin(), out.end(), [&](const LoopArm& x, const LoopArm& y) {
    return edges(L.corners[0], x.corners[0]) < edges(L.corners[0], y.corners[0]);
  });
  return out;
}

}  // namespace

std::vector<PolycubeLoop> automatic_corners(const mesh::TriMesh& m, const std::vector<std::vector<int>>& loops,
                                            const SheetFrame& fr, bool arms) {
  std::vector<PolycubeLoop> out = make_loops(m, loops, fr);
  for (std::size_t l = 0; l < out.size(); ++l) {
    PolycubeLoop& L = out[l];
    const std::size_t n = L.vertices.size();
    if (arms && L.outer) {
      std::vector<std::vector<int>> others;
      for (std::size_t k = 0; k < loops.size(); ++k)
        if (k != l) others.push_back(loops[k]);
      const std::vector<SheetLobe> lobes = find_lobes(m, L.vertices, others);
      if (!lobes.empty() && place_corners(m, L, fr, lobe_mask(n, lobes))) {
        L.arms = loop_arms(m, L, lobes);
        continue;
      }
    }
    place_corners(m, L, fr, std::vector<char>(n, 0));
  }
  return out;
}

std::vector<PolycubeLoop> corners_from_points(const mesh::TriMesh& m, const std::vector<std::vector<int>>& loops,
                                              const std::vector<Eigen::Vector3d>& points, const SheetFrame& fr) {
  std::vector<PolycubeLoop> out = make_loops(m, loops, fr);
  std::vector<std::vector<int>> picked(loops.size());
  std::set<int> used;
  for (std::size_t p = 0; p < points.size(); ++p) {
    double bd = 1e300;
    int bl = -1, bi = -1;
    for (std::size_t l = 0; l < loops.size(); ++l)
      for (std::size_t i = 0; i < loops[l].size(); ++i) {
        const double d = (P(m, loops[l][i]) - points[p]).squaredNorm();
        if (d < bd) {
          bd = d;
          bl = static_cast<int>(l);
          bi = static_cast<int>(i);
        }
      }
    if (!used.insert(loops[bl][bi]).second)
      throw bad_input("polycube: corner point " + std::to_string(p) + " snaps to the same boundary vertex as another");
    picked[bl].push_back(bi);
  }
  for (std::size_t l = 0; l < loops.size(); ++l) {
    if (picked[l].size() != 4)
      throw bad_input("polycube: boundary loop " + std::to_string(l) + (out[l].outer ? " (outer)" : " (a hole)") +
                      " got " + std::to_string(picked[l].size()) +
                      " corner points; every loop needs exactly four (give four points near each loop, or none "
                      "for automatic corners)");
    std::sort(picked[l].begin(), picked[l].end());
    for (int k = 0; k < 4; ++k) out[l].corners[k] = picked[l][k];
    assign_sides(m, out[l], fr);
  }
  return out;
}

int refine_hole_corners(mesh::TriMesh& m, const std::vector<PolycubeLoop>& loops, int min_fan) {
  int total = 0;
  for (int pass = 0; pass < 8; ++pass) {
    std::unordered_map<std::uint64_t, std::vector<int>> ef;
    for (int f = 0; f < m.F.rows(); ++f)
      for (int k = 0; k < 3; ++k) ef[edge_key(m.F(f, k), m.F(f, (k + 1) % 3))].push_back(f);
    std::map<std::uint64_t, int> mid;
    std::vector<Eigen::RowVector3d> newV;
    std::vector<int> reflex;
    for (const PolycubeLoop& L : loops) {
      for (int k = 0; k < 4 && !L.outer; ++k) reflex.push_back(L.vertices[static_cast<std::size_t>(L.corners[k])]);
      for (const LoopArm& arm : L.arms)
        for (int k : {0, 3}) reflex.push_back(L.vertices[static_cast<std::size_t>(arm.corners[static_cast<std::size_t>(k)])]);
    }
    for (const int c : reflex) {
      std::vector<std::uint64_t> opposite;
      int fan = 0;
      for (int f = 0; f < m.F.rows(); ++f)
        for (int j = 0; j < 3; ++j)
          if (m.F(f, j) == c) {
            ++fan;
            opposite.push_back(edge_key(m.F(f, (j + 1) % 3), m.F(f, (j + 2) % 3)));
          }
      if (fan >= min_fan) continue;
      for (std::uint64_t e : opposite)
        if (ef[e].size() == 2 && !mid.count(e)) {
          mid[e] = static_cast<int>(m.V.rows() + static_cast<Eigen::Index>(newV.size()));
          newV.push_back(0.5 * (m.V.row(static_cast<int>(e >> 32)) + m.V.row(static_cast<int>(e & 0xffffffffu))));
        }
    }
    if (newV.empty()) return total;
    total += static_cast<int>(newV.size());
    append_split(m, newV, faces_split_at(m, mid));
  }
  return total;
}

// A long sheet whose ends are narrow (a propeller: corners at the blade
// tips) gets a rectangle as short as its ends, too short for its holes. When
// a hole takes more than half of the short side, that side grows to the
// sheet's mean width, area / (long side).
template <class Sizes>
void grow_to_fit_holes(const mesh::TriMesh& m, const std::vector<PolycubeLoop>& loops, const Sizes& sizes,
                       RectilinearDomain& dom) {
  double area = 0.0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    area += face_area(m, f);
  Eigen::Vector2d need = Eigen::Vector2d::Zero();
  for (const PolycubeLoop& L : loops)
    if (!L.outer) {
      const Eigen::Vector2d h = sizes(L);
      area += h(0) * h(1);
      need = need.cwiseMax(h);
    }
  double& short_side = dom.width < dom.height ? dom.width : dom.height;
  const double long_side = std::max(dom.width, dom.height);
  const double need_short = dom.width < dom.height ? need(0) : need(1);
  if (short_side >= 2.0 * need_short) return;
  short_side = std::max(short_side, area / long_side);
}

namespace {

bool horizontal(DomainSide side) { return side == DomainSide::Bottom || side == DomainSide::Top; }

// Box sides closer than this share of the domain's short side are merged
// (merge_close_sides): far below the 4 % gap kept between holes and the
// third of an arm's width kept between arms on a side.
constexpr double kCloseSides = 0.01;

// Number of loop edges from position a forward to position b.
int edges_between(std::size_t n, int a, int b) { return (b - a + static_cast<int>(n)) % static_cast<int>(n); }

bool arm_in_segment(const PolycubeLoop& L, const LoopArm& arm, int k) {
  const std::size_t n = L.vertices.size();
  return edges_between(n, L.corners[k], arm.corners[0]) < edges_between(n, L.corners[k], L.corners[(k + 1) % 4]);
}

// Length of segment k of a loop, a lobe's boundary counted as its arm's width.
double segment_length(const PolycubeLoop& L, const std::vector<double>& s, int k) {
  double length = arc_between(s, L.corners[k], L.corners[(k + 1) % 4]);
  for (const LoopArm& arm : L.arms)
    if (arm_in_segment(L, arm, k)) length -= arc_between(s, arm.corners[0], arm.corners[3]) - arm.width;
  return length;
}

// Along one side: the gaps before, between and after its arms, and the
// arms' widths, made to add up to the side's length with every gap at least
// a third of the arms beside it (fingers side by side leave only a short
// boundary between them; two reflex corners that close fold the map).
void spread_on_side(std::vector<double>& gaps, std::vector<double>& widths, double side) {
  for (std::size_t i = 0; i < gaps.size(); ++i) {
    double beside = 0.0;
    if (i > 0) beside = std::max(beside, widths[i - 1]);
    if (i < widths.size()) beside = std::max(beside, widths[i]);
    gaps[i] = std::max(gaps[i], beside / 3.0);
  }
  double total = 0.0;
  for (double g : gaps) total += g;
  for (double w : widths) total += w;
  for (double& g : gaps) g *= side / total;
  for (double& w : widths) w *= side / total;
}

// The outer loop's arms on its domain: along each side in the proportions of
// the loop's segment (each lobe counted as its arm's width), spread.
std::vector<DomainArm> domain_arms(const mesh::TriMesh& m, const PolycubeLoop& L, const RectilinearDomain& dom) {
  const std::vector<double> s = arc_lengths(m, L.vertices);
  std::vector<DomainArm> out;
  for (int k = 0; k < 4; ++k) {
    std::vector<double> gaps, widths, lengths;
    int at = L.corners[k];
    for (const LoopArm& arm : L.arms) {
      if (!arm_in_segment(L, arm, k)) continue;
      gaps.push_back(arc_between(s, at, arm.corners[0]));
      widths.push_back(arm.width);
      lengths.push_back(arm.length);
      at = arm.corners[3];
    }
    if (widths.empty()) continue;
    gaps.push_back(arc_between(s, at, L.corners[(k + 1) % 4]));
    spread_on_side(gaps, widths, horizontal(L.sides[k]) ? dom.width : dom.height);
    double t = 0.0;
    for (std::size_t i = 0; i < widths.size(); ++i) {
      t += gaps[i];
      out.push_back({L.sides[k], t, t + widths[i], lengths[i]});
      t += widths[i];
    }
  }
  return out;
}

}  // namespace

RectilinearDomain rectilinear_domain(const mesh::TriMesh& m, const std::vector<PolycubeLoop>& loops) {
  RectilinearDomain dom;
  auto sizes = [&](const PolycubeLoop& L) {
    const std::vector<double> s = arc_lengths(m, L.vertices);
    double w = 0.0, h = 0.0;
    for (int k = 0; k < 4; ++k) (horizontal(L.sides[k]) ? w : h) += 0.5 * segment_length(L, s, k);
    return Eigen::Vector2d(w, h);
  };
  int outer = -1;
  for (std::size_t l = 0; l < loops.size(); ++l)
    if (loops[l].outer) outer = static_cast<int>(l);
  if (outer < 0) throw bad_input("polycube: no outer loop");
  const Eigen::Vector2d WH = sizes(loops[outer]);
  dom.width = WH(0);
  dom.height = WH(1);
  if (loops.size() > 1) grow_to_fit_holes(m, loops, sizes, dom);
  dom.arms = domain_arms(m, loops[outer], dom);
  const double close = kCloseSides * std::min(dom.width, dom.height);
  if (loops.size() == 1) {
    merge_close_sides(dom, close);
    return dom;
  }

  // Harmonic map with the outer loop on the rectangle and the holes free.
  RectilinearDomain outer_only = dom;
  std::vector<PolycubeLoop> just_outer{loops[outer]};
  std::vector<char> fixed;
  const Eigen::MatrixXd buv = boundary_uv(m, boundary_segments(just_outer, outer_only), fixed);
  std::vector<int> fixed_list;
  for (std::size_t i = 0; i < fixed.size(); ++i)
    if (fixed[i]) fixed_list.push_back(static_cast<int>(i));
  HarmonicSolver solver(tri_cotan_laplacian(m.V, m.F), {fixed_list});
  Eigen::MatrixXd uv0(m.V.rows(), 2);
  for (int c = 0; c < 2; ++c) uv0.col(c) = solver.solve_with(buv.col(c));

  std::vector<Eigen::Vector2d> centers, hs;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    if (loops[l].outer) continue;
    const auto& vs = loops[l].vertices;
    Eigen::Vector2d c = Eigen::Vector2d::Zero();
    double total = 0.0;
    for (std::size_t i = 0; i < vs.size(); ++i) {
      const int a = vs[i], b = vs[(i + 1) % vs.size()];
      const double w = (P(m, b) - P(m, a)).norm();
      c += w * 0.5 * (uv0.row(a) + uv0.row(b)).transpose();
      total += w;
    }
    centers.push_back(c / total);
    hs.push_back(sizes(loops[l]));
    dom.hole_loop.push_back(static_cast<int>(l));
  }
  const double gap = 0.04 * std::min(dom.width, dom.height);
  auto build = [&](double scale) {
    std::vector<Eigen::Vector4d> holes;
    for (std::size_t h = 0; h < centers.size(); ++h) {
      const Eigen::Vector2d half = 0.5 * scale * hs[h];
      Eigen::Vector2d c = centers[h];
      c(0) = std::clamp(c(0), gap + half(0), dom.width - gap - half(0));
      c(1) = std::clamp(c(1), gap + half(1), dom.height - gap - half(1));
      holes.emplace_back(c(0) - half(0), c(1) - half(1), c(0) + half(0), c(1) + half(1));
    }
    return holes;
  };
  auto valid = [&](const std::vector<Eigen::Vector4d>& holes) {
    for (std::size_t a = 0; a < holes.size(); ++a) {
      const Eigen::Vector4d& h = holes[a];
      if (h(0) < gap - 1e-12 || h(1) < gap - 1e-12 || h(2) > dom.width - gap + 1e-12 || h(3) > dom.height - gap + 1e-12 ||
          !(h(2) > h(0)) || !(h(3) > h(1)))
        return false;
      for (std::size_t b = a + 1; b < holes.size(); ++b) {
        const Eigen::Vector4d& g = holes[b];
        const bool apart = h(2) + gap <= g(0) || g(2) + gap <= h(0) || h(3) + gap <= g(1) || g(3) + gap <= h(1);
        if (!apart) return false;
      }
    }
    return true;
  };
  double scale = 1.0;
  std::vector<Eigen::Vector4d> holes = build(scale);
  for (int it = 0; it < 200 && !valid(holes); ++it) holes = build(scale *= 0.95);
  if (!valid(holes))
    throw bad_input("polycube: the holes of M0trim do not fit as separate rectangles in the outer rectangle; "
                    "give corner points in the case file");
  // Align nearby sides of the same kind (e.g. holes in a row share their bottom and top).
  std::vector<Eigen::Vector4d> aligned = holes;
  const double tol = 0.05 * std::min(dom.width, dom.height);
  for (int k = 0; k < 4; ++k)
    for (std::size_t a = 0; a < aligned.size(); ++a) {
      std::vector<std::size_t> group{a};
      for (std::size_t b = 0; b < aligned.size(); ++b)
        if (b != a && std::abs(holes[b](k) - holes[a](k)) < tol) group.push_back(b);
      if (group.size() < 2) continue;
      double mean = 0.0;
      for (std::size_t g : group) mean += holes[g](k);
      mean /= static_cast<double>(group.size());
      for (std::size_t g : group) aligned[g](k) = mean;
    }
  dom.holes = valid(aligned) ? aligned : holes;
  RectilinearDomain merged = dom;
  merge_close_sides(merged, close);
  return valid(merged.holes) ? merged : dom;
}

namespace {

Eigen::Vector2d outward_normal(DomainSide side) {
  switch (side) {
    case DomainSide::Bottom: return {0.0, -1.0};
    case DomainSide::Right: return {1.0, 0.0};
    case DomainSide::Top: return {0.0, 1.0};
    case DomainSide::Left: return {-1.0, 0.0};
  }
  return {0.0, 0.0};
}

// The side of the outer rectangle a point moves along (its first corner and
// unit direction in the loop's sense).
std::pair<Eigen::Vector2d, Eigen::Vector2d> side_line(const RectilinearDomain& d, DomainSide side) {
  switch (side) {
    case DomainSide::Bottom: return {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(1.0, 0.0)};
    case DomainSide::Right: return {Eigen::Vector2d(d.width, 0.0), Eigen::Vector2d(0.0, 1.0)};
    case DomainSide::Top: return {Eigen::Vector2d(d.width, d.height), Eigen::Vector2d(-1.0, 0.0)};
    case DomainSide::Left: return {Eigen::Vector2d(0.0, d.height), Eigen::Vector2d(0.0, -1.0)};
  }
  return {};
}

// The domain side a straight piece of boundary is on, by the direction it
// leaves the domain (outer loop: the domain on the left of travel).
DomainSide side_of_travel(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  if (std::abs(d.x()) >= std::abs(d.y())) return d.x() > 0.0 ? DomainSide::Bottom : DomainSide::Top;
  return d.y() > 0.0 ? DomainSide::Right : DomainSide::Left;
}

// The positions on the outer loop that side k runs through: its corner, the
// corners of the arms on it, the next corner.
std::vector<int> side_positions(const PolycubeLoop& L, int k) {
  std::vector<int> pos{L.corners[k]};
  for (const LoopArm& arm : L.arms)
    if (arm_in_segment(L, arm, k)) pos.insert(pos.end(), arm.corners.begin(), arm.corners.end());
  pos.push_back(L.corners[(k + 1) % 4]);
  return pos;
}

// The outer loop's segments: per side of the rectangle, the pieces between
// its corners and its arms' corners.
void outer_segments(const PolycubeLoop& L, int loop, const RectilinearDomain& dom, std::vector<BoundarySegment>& segs) {
  const std::size_t n = L.vertices.size();
  for (int k = 0; k < 4; ++k) {
    const std::vector<int> pos = side_positions(L, k);
    const std::vector<Eigen::Vector2d> pts = side_walk(dom, L.sides[k]);
    if (pts.size() != pos.size()) throw internal_error("polycube: an arm of the domain has no lobe on its side of the loop");
    for (std::size_t i = 0; i + 1 < pos.size(); ++i) {
      BoundarySegment seg;
      seg.loop = loop;
      seg.side = side_of_travel(pts[i], pts[i + 1]);
      seg.u_iso = !horizontal(seg.side);
      seg.value = seg.u_iso ? pts[i].x() : pts[i].y();
      for (std::size_t p = static_cast<std::size_t>(pos[i]);; p = (p + 1) % n) {
        seg.vertices.push_back(L.vertices[p]);
        if (static_cast<int>(p) == pos[i + 1] && seg.vertices.size() > 1) break;
      }
      segs.push_back(seg);
    }
  }
}

}  // namespace

bool arms_apart(const std::vector<PolycubeLoop>& loops) {
  for (const PolycubeLoop& L : loops)
    for (int k = 0; L.outer && k < 4; ++k) {
      const std::vector<int> pos = side_positions(L, k);
      for (std::size_t i = 0; i + 1 < pos.size(); ++i)
        if (pos[i] == pos[i + 1]) return false;
    }
  return true;
}

Eigen::Vector4d arm_box(const RectilinearDomain& d, const DomainArm& arm) {
  const auto [start, dir] = side_line(d, arm.side);
  const Eigen::Vector2d a = start + arm.from * dir, b = start + arm.to * dir;
  const Eigen::Vector2d c = b + arm.length * outward_normal(arm.side);
  return Eigen::Vector4d(std::min(a.x(), c.x()), std::min(a.y(), c.y()), std::max(a.x(), c.x()), std::max(a.y(), c.y()));
}

DomainArm arm_from_box(DomainSide side, const Eigen::Vector4d& box, double width, double height) {
  DomainArm a;
  a.side = side;
  switch (side) {
    case DomainSide::Bottom: a.from = box(0), a.to = box(2), a.length = -box(1); break;
    case DomainSide::Right: a.from = box(1), a.to = box(3), a.length = box(2) - width; break;
    case DomainSide::Top: a.from = width - box(2), a.to = width - box(0), a.length = box(3) - height; break;
    case DomainSide::Left: a.from = height - box(3), a.to = height - box(1), a.length = -box(0); break;
  }
  return a;
}

bool inside_domain(const RectilinearDomain& domain, const Eigen::Vector2d& p) {
  bool in = p.x() > 0.0 && p.x() < domain.width && p.y() > 0.0 && p.y() < domain.height;
  for (const DomainArm& arm : domain.arms) {
    // Open except where it joins the rectangle (that line is inside).
    const Eigen::Vector4d b = arm_box(domain, arm);
    const bool u_in = p.x() > b(0) && p.x() < b(2), v_in = p.y() > b(1) && p.y() < b(3);
    switch (arm.side) {
      case DomainSide::Bottom: in = in || (u_in && p.y() > b(1) && p.y() <= b(3)); break;
      case DomainSide::Top: in = in || (u_in && p.y() >= b(1) && p.y() < b(3)); break;
      case DomainSide::Left: in = in || (v_in && p.x() > b(0) && p.x() <= b(2)); break;
      case DomainSide::Right: in = in || (v_in && p.x() >= b(0) && p.x() < b(2)); break;
    }
  }
  if (!in) return false;
  for (const auto& h : domain.holes)
    if (p.x() >= h(0) && p.x() <= h(2) && p.y() >= h(1) && p.y() <= h(3)) return false;
  return true;
}

std::vector<Eigen::Vector2d> side_walk(const RectilinearDomain& d, DomainSide side) {
  const auto [start, dir] = side_line(d, side);
  const Eigen::Vector2d out = outward_normal(side);
  std::vector<Eigen::Vector2d> pts{start};
  for (const DomainArm& arm : d.arms) {
    if (arm.side != side) continue;
    const Eigen::Vector2d a = start + arm.from * dir, b = start + arm.to * dir;
    pts.insert(pts.end(), {a, a + arm.length * out, b + arm.length * out, b});
  }
  pts.push_back(start + (horizontal(side) ? d.width : d.height) * dir);
  return pts;
}

std::vector<BoundarySegment> boundary_segments(const std::vector<PolycubeLoop>& loops, const RectilinearDomain& dom) {
  std::vector<BoundarySegment> segs;
  int hole = 0;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const PolycubeLoop& L = loops[l];
    if (L.outer) {
      outer_segments(L, static_cast<int>(l), dom, segs);
      continue;
    }
    if (hole >= static_cast<int>(dom.holes.size())) throw bad_input("polycube: more inner loops than holes");
    const Eigen::Vector4d box = dom.holes[static_cast<std::size_t>(hole++)];
    const std::size_t n = L.vertices.size();
    for (int k = 0; k < 4; ++k) {
      BoundarySegment s;
      s.loop = static_cast<int>(l);
      s.side = L.sides[k];
      s.u_iso = s.side == DomainSide::Left || s.side == DomainSide::Right;
      s.value = s.side == DomainSide::Left ? box(0) : s.side == DomainSide::Right ? box(2)
              : s.side == DomainSide::Bottom ? box(1) : box(3);
      for (std::size_t i = static_cast<std::size_t>(L.corners[k]);; i = (i + 1) % n) {
        s.vertices.push_back(L.vertices[i]);
        if (static_cast<int>(i) == L.corners[(k + 1) % 4] && s.vertices.size() > 1) break;
      }
      segs.push_back(s);
    }
  }
  return segs;
}

Eigen::MatrixXd boundary_uv(const mesh::TriMesh& m, const std::vector<BoundarySegment>& segs, std::vector<char>& fixed) {
  Eigen::MatrixXd uv = Eigen::MatrixXd::Zero(m.V.rows(), 2);
  fixed.assign(static_cast<std::size_t>(m.V.rows()), 0);
  // Corners: a corner is the end of one segment (iso in one coordinate) and the
  // start of the next (iso in the other), so both values are known exactly.
  for (std::size_t k = 0; k < segs.size(); ++k) {
    const BoundarySegment& s = segs[k];
    const BoundarySegment* prev = nullptr;
    const BoundarySegment* next = nullptr;
    for (const BoundarySegment& t : segs)
      if (t.loop == s.loop) {
        if (t.vertices.back() == s.vertices.front()) prev = &t;
        if (t.vertices.front() == s.vertices.back()) next = &t;
      }
    if (!prev || !next || prev->u_iso == s.u_iso || next->u_iso == s.u_iso)
      throw internal_error("polycube: segments of a loop do not alternate between u and v");
    Eigen::Vector2d a, b;  // start and end corner
    a(s.u_iso ? 0 : 1) = s.value;
    a(prev->u_iso ? 0 : 1) = prev->value;
    b(s.u_iso ? 0 : 1) = s.value;
    b(next->u_iso ? 0 : 1) = next->value;
    double total = 0.0;
    for (std::size_t i = 1; i < s.vertices.size(); ++i) total += (P(m, s.vertices[i]) - P(m, s.vertices[i - 1])).norm();
    double acc = 0.0;
    for (std::size_t i = 0; i < s.vertices.size(); ++i) {
      if (i > 0) acc += (P(m, s.vertices[i]) - P(m, s.vertices[i - 1])).norm();
      const double t = i + 1 == s.vertices.size() ? 1.0 : (total > 0 ? acc / total : 0.0);
      Eigen::Vector2d x = (1.0 - t) * a + t * b;
      x(s.u_iso ? 0 : 1) = s.value;  // exactly iso-parametric
      if (i == 0) x = a;
      if (i + 1 == s.vertices.size()) x = b;
      uv.row(s.vertices[i]) = x.transpose();
      fixed[static_cast<std::size_t>(s.vertices[i])] = 1;
    }
  }
  return uv;
}

Eigen::MatrixXd harmonic_uv(const mesh::TriMesh& m, const Eigen::MatrixXd& fixed_uv, const std::vector<char>& fixed,
                            UvWeights weights) {
  const Eigen::Index n = m.V.rows();
  if (weights == UvWeights::Cotangent) {
    std::vector<int> list;
    for (Eigen::Index i = 0; i < n; ++i)
      if (fixed[static_cast<std::size_t>(i)]) list.push_back(static_cast<int>(i));
    HarmonicSolver solver(tri_cotan_laplacian(m.V, m.F), {list});
    Eigen::MatrixXd uv(n, 2);
    for (int c = 0; c < 2; ++c) uv.col(c) = solver.solve_with(fixed_uv.col(c));
    return uv;
  }
  // Floater's mean-value weights: w_ij = (tan(a/2) + tan(b/2)) / |x_j - x_i|,
  // a and b the angles at x_i of the two triangles along edge ij. Positive,
  // so the map is a convex combination map.
  std::vector<Eigen::Triplet<double>> trip;
  for (int f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int i = m.F(f, k), j = m.F(f, (k + 1) % 3), l = m.F(f, (k + 2) % 3);
      if (fixed[static_cast<std::size_t>(i)]) continue;
      const Eigen::Vector3d eij = P(m, j) - P(m, i), eil = P(m, l) - P(m, i);
      const double angle = angle_radians(eij, eil);
      const double t = std::tan(0.5 * angle);
      // angle at i lies between edges ij and il: it contributes to both weights
      trip.emplace_back(i, j, -t / eij.norm());
      trip.emplace_back(i, l, -t / eil.norm());
      trip.emplace_back(i, i, t / eij.norm() + t / eil.norm());
    }
  for (Eigen::Index i = 0; i < n; ++i)
    if (fixed[static_cast<std::size_t>(i)]) trip.emplace_back(static_cast<int>(i), static_cast<int>(i), 1.0);
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(trip.begin(), trip.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(A);
  if (lu.info() != Eigen::Success) throw internal_error("polycube: the mean-value system could not be factored");
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 2);
  for (Eigen::Index i = 0; i < n; ++i)
    if (fixed[static_cast<std::size_t>(i)]) rhs.row(i) = fixed_uv.row(i);
  Eigen::MatrixXd uv = lu.solve(rhs);
  for (Eigen::Index i = 0; i < n; ++i)
    if (fixed[static_cast<std::size_t>(i)]) uv.row(i) = fixed_uv.row(i);  // exact
  return uv;
}

int untangle_uv(const mesh::TriMesh& m, Eigen::MatrixXd& uv, const std::vector<char>& fixed, int rounds) {
  std::vector<std::vector<int>> vf(static_cast<std::size_t>(m.V.rows()));
  for (int f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) vf[static_cast<std::size_t>(m.F(f, k))].push_back(f);
  auto area = [&](int f) {
    const int a = m.F(f, 0), b = m.F(f, 1), c = m.F(f, 2);
    return (uv(b, 0) - uv(a, 0)) * (uv(c, 1) - uv(a, 1)) - (uv(c, 0) - uv(a, 0)) * (uv(b, 1) - uv(a, 1));
  };
  int folded = 0;
  for (int round = 0; round <= rounds; ++round) {
    std::set<int> movers;
    folded = 0;
    for (int f = 0; f < m.F.rows(); ++f)
      if (!(area(f) > 0.0)) {
        ++folded;
        for (int k = 0; k < 3; ++k)
          if (!fixed[static_cast<std::size_t>(m.F(f, k))]) movers.insert(m.F(f, k));
      }
    if (folded == 0 || round == rounds || movers.empty()) break;
    for (int v : movers) {
      // Half-planes: for face (v, a, b) in order, x must lie left of a -> b.
      std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> hp;
      double scale = 1e300;
      for (int f : vf[static_cast<std::size_t>(v)]) {
        int j = 0;
        while (m.F(f, j) != v) ++j;
        const Eigen::Vector2d a = uv.row(m.F(f, (j + 1) % 3)).transpose(), b = uv.row(m.F(f, (j + 2) % 3)).transpose();
        hp.emplace_back(a, b);
        scale = std::min(scale, (b - a).norm());
      }
      Eigen::Vector2d x = uv.row(v).transpose();
      const double margin = 1e-3 * scale;
      for (int it = 0; it < 200; ++it) {
        bool ok = true;
        for (const auto& [a, b] : hp) {
          const Eigen::Vector2d d = b - a;
          const Eigen::Vector2d n(-d(1), d(0));  // left normal
          const double nn = n.norm();
          if (!(nn > 0)) continue;
          const double s = n.dot(x - a) / nn;
          if (s < margin) {
            ok = false;
            x += (margin - s) * n / nn;
          }
        }
        if (ok) break;
      }
      uv.row(v) = x.transpose();
    }
  }
  return folded;
}

Eigen::VectorXd uv_jacobians(const mesh::TriMesh& m, const Eigen::MatrixXd& uv) {
  Eigen::VectorXd J(m.F.rows());
  for (int f = 0; f < m.F.rows(); ++f) {
    const int a = m.F(f, 0), b = m.F(f, 1), c = m.F(f, 2);
    const double uva = 0.5 * ((uv(b, 0) - uv(a, 0)) * (uv(c, 1) - uv(a, 1)) - (uv(c, 0) - uv(a, 0)) * (uv(b, 1) - uv(a, 1)));
    const double A = face_area(m, f);
    J(f) = A > 0 ? uva / A : (uva > 0 ? 1e300 : -1e300);
  }
  return J;
}

double squeezed_share(const mesh::TriMesh& sheet, const Eigen::VectorXd& jacobian, double factor) {
  std::vector<std::pair<double, double>> by_jacobian;  // (J, 3D area)
  double total = 0.0;
  for (Eigen::Index f = 0; f < sheet.F.rows(); ++f) {
    const double area = face_area(sheet, f);
    by_jacobian.emplace_back(jacobian(f), area);
    total += area;
  }
  if (!(total > 0.0)) return 0.0;
  std::sort(by_jacobian.begin(), by_jacobian.end());
  double run = 0.0, median = 0.0;
  for (const auto& [J, area] : by_jacobian) {
    run += area;
    if (run >= 0.5 * total) {
      median = J;
      break;
    }
  }
  double squeezed = 0.0;
  for (const auto& [J, area] : by_jacobian) {
    if (!(J < factor * median)) break;
    squeezed += area;
  }
  return squeezed / total;
}

namespace {

void sort_unique(std::vector<double>& x) {
  std::sort(x.begin(), x.end());
  x.erase(std::unique(x.begin(), x.end()), x.end());
}

// Every interval of `lines` longer than max_aspect times the longest
// interval of `across` is cut into equal parts no longer than that.
void split_long_intervals(std::vector<double>& lines, const std::vector<double>& across, double max_aspect) {
  double longest = 0.0;
  for (std::size_t i = 1; i < across.size(); ++i) longest = std::max(longest, across[i] - across[i - 1]);
  const double limit = max_aspect * longest;
  std::vector<double> out;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const int parts = static_cast<int>(std::ceil((lines[i] - lines[i - 1]) / limit - 1e-9));
    for (int k = 1; k < parts; ++k)
      out.push_back(lines[i - 1] + (lines[i] - lines[i - 1]) * static_cast<double>(k) / parts);
  }
  lines.insert(lines.end(), out.begin(), out.end());
  sort_unique(lines);
}

// Adds each line strictly inside (0, extent) that is not within a
// millionth of the extent of one already there.
void add_lines(std::vector<double>& lines, const std::vector<double>& extra, double extent) {
  const double tol = 1e-6 * extent;
  for (const double x : extra) {
    if (!(x > tol && x < extent - tol)) continue;
    const bool near = std::any_of(lines.begin(), lines.end(), [&](double y) { return std::abs(x - y) <= tol; });
    if (!near) lines.push_back(x);
  }
  sort_unique(lines);
}

}  // namespace

std::vector<Eigen::Vector4d> domain_rectangles(const RectilinearDomain& dom, double max_aspect,
                                               const GridLines& extra) {
  std::vector<double> xs{0.0, dom.width}, ys{0.0, dom.height};
  std::vector<Eigen::Vector4d> boxes = dom.holes;
  for (const DomainArm& arm : dom.arms) boxes.push_back(arm_box(dom, arm));
  for (const auto& h : boxes) {
    xs.push_back(h(0));
    xs.push_back(h(2));
    ys.push_back(h(1));
    ys.push_back(h(3));
  }
  sort_unique(xs);
  sort_unique(ys);
  if (max_aspect > 0.0) {
    const std::vector<double> xs0 = xs, ys0 = ys;
    split_long_intervals(xs, ys0, max_aspect);
    split_long_intervals(ys, xs0, max_aspect);
  }
  add_lines(xs, extra.u, dom.width);
  add_lines(ys, extra.v, dom.height);
  std::vector<Eigen::Vector4d> rects;
  for (std::size_t j = 0; j + 1 < ys.size(); ++j)
    for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
      const Eigen::Vector2d centre(0.5 * (xs[i] + xs[i + 1]), 0.5 * (ys[j] + ys[j + 1]));
      if (inside_domain(dom, centre)) rects.emplace_back(xs[i], ys[j], xs[i + 1], ys[j + 1]);
    }
  return rects;
}

// The boundary segments and the (u, v) map onto pc.domain: cotangent weights,
// then mean-value weights, each untangled when it folds.
// Each arm's neck path spread by 3D arc length on the line its arm joins the
// rectangle by (arms and domain arms are in the same order).
void fix_neck_paths(const mesh::TriMesh& sheet, const Polycube2D& pc, Eigen::MatrixXd& uv, std::vector<char>& fixed) {
  std::size_t next = 0;
  for (const PolycubeLoop& L : pc.loops)
    for (const LoopArm& arm : L.arms) {
      const DomainArm& d = pc.domain.arms.at(next++);
      const auto [start, dir] = side_line(pc.domain, d.side);
      const Eigen::Vector2d a = start + d.from * dir, b = start + d.to * dir;
      detail::spread_on_segment(sheet, arm.neck_path, a, b, uv, fixed);
    }
}

void map_to_domain(const mesh::TriMesh& sheet, Polycube2D& pc) {
  pc.segments = boundary_segments(pc.loops, pc.domain);
  std::vector<char> fixed;
  Eigen::MatrixXd buv = boundary_uv(sheet, pc.segments, fixed);
  fix_neck_paths(sheet, pc, buv, fixed);
  fix_hole_cuts(sheet, pc, buv, fixed);
  for (UvWeights w : {UvWeights::Cotangent, UvWeights::MeanValue}) {
    pc.weights.clear();
    pc.uv = harmonic_uv(sheet, buv, fixed, w);
    if (uv_jacobians(sheet, pc.uv).minCoeff() <= 0.0 && untangle_uv(sheet, pc.uv, fixed) == 0)
      pc.weights = w == UvWeights::Cotangent ? "cotangent, untangled" : "mean value, untangled";
    pc.jacobian = uv_jacobians(sheet, pc.uv);
    pc.min_jacobian = pc.jacobian.minCoeff();
    pc.max_jacobian = pc.jacobian.maxCoeff();
    if (pc.weights.find("untangled") == std::string::npos) pc.weights = w == UvWeights::Cotangent ? "cotangent" : "mean value";
    if (pc.min_jacobian > 0.0) break;
  }
}

void shrink_holes(RectilinearDomain& dom, double factor) {
  for (Eigen::Vector4d& h : dom.holes) {
    const Eigen::Vector2d c(0.5 * (h(0) + h(2)), 0.5 * (h(1) + h(3)));
    const Eigen::Vector2d half(0.5 * factor * (h(2) - h(0)), 0.5 * factor * (h(3) - h(1)));
    h << c(0) - half(0), c(1) - half(1), c(0) + half(0), c(1) + half(1);
  }
}

namespace {

// Each arm's neck path: a shortest edge path between its neck's ends that
// touches no other boundary vertex and no earlier neck. False when one has none.
bool find_neck_paths(const mesh::TriMesh& sheet, std::vector<PolycubeLoop>& loops) {
  const detail::EdgeGraph graph = detail::edge_graph(sheet);
  std::vector<char> blocked(static_cast<std::size_t>(sheet.V.rows()), 0);
  for (const PolycubeLoop& L : loops)
    for (int v : L.vertices) blocked[static_cast<std::size_t>(v)] = 1;
  for (PolycubeLoop& L : loops)
    for (LoopArm& arm : L.arms) {
      const int a = L.vertices[static_cast<std::size_t>(arm.corners[0])], b = L.vertices[static_cast<std::size_t>(arm.corners[3])];
      const detail::ShortestPaths paths = detail::shortest_paths(graph, a, b, &blocked);
      if (paths.prev[static_cast<std::size_t>(b)] < 0) return false;
      arm.neck_path = detail::path_to(paths, b);
      for (int v : arm.neck_path) blocked[static_cast<std::size_t>(v)] = 1;
    }
  return true;
}

// Splits every edge inside the sheet whose two ends are fixed (on a boundary
// loop, a neck path or one of `paths`) and that is no such path's own edge: a triangle with
// three fixed vertices could be flat (three vertices on one straight line of
// the domain), and a convex-combination map is bijective only without such
// chords. The loops and the paths keep their vertices. Returns the splits.
int split_fixed_chords(mesh::TriMesh& m, const std::vector<PolycubeLoop>& loops,
                       const std::vector<std::vector<int>>& paths = {}) {
  int total = 0;
  for (int pass = 0; pass < 8; ++pass) {
    std::vector<char> fixed(static_cast<std::size_t>(m.V.rows()), 0);
    std::unordered_set<std::uint64_t> path_edges;
    for (const PolycubeLoop& L : loops) {
      for (int v : L.vertices) fixed[static_cast<std::size_t>(v)] = 1;
      for (const LoopArm& arm : L.arms) {
        for (int v : arm.neck_path) fixed[static_cast<std::size_t>(v)] = 1;
        for (std::size_t i = 1; i < arm.neck_path.size(); ++i) path_edges.insert(edge_key(arm.neck_path[i - 1], arm.neck_path[i]));
      }
    }
    for (const std::vector<int>& path : paths) {
      for (int v : path) fixed[static_cast<std::size_t>(v)] = 1;
      for (std::size_t i = 1; i < path.size(); ++i) path_edges.insert(edge_key(path[i - 1], path[i]));
    }
    std::unordered_map<std::uint64_t, int> faces_of_edge;
    for (int f = 0; f < m.F.rows(); ++f)
      for (int k = 0; k < 3; ++k) ++faces_of_edge[edge_key(m.F(f, k), m.F(f, (k + 1) % 3))];
    std::map<std::uint64_t, int> mid;
    std::vector<Eigen::RowVector3d> newV;
    std::vector<char> touched(static_cast<std::size_t>(m.F.rows()), 0);
    for (int f = 0; f < m.F.rows(); ++f)
      for (int k = 0; k < 3; ++k) {
        const int a = m.F(f, k), b = m.F(f, (k + 1) % 3);
        const std::uint64_t key = edge_key(a, b);
        if (!fixed[static_cast<std::size_t>(a)] || !fixed[static_cast<std::size_t>(b)] || faces_of_edge[key] != 2 ||
            path_edges.count(key) || mid.count(key))
          continue;
        mid[key] = static_cast<int>(m.V.rows() + static_cast<Eigen::Index>(newV.size()));
        newV.push_back(0.5 * (m.V.row(a) + m.V.row(b)));
      }
    if (newV.empty()) return total;
    total += static_cast<int>(newV.size());
    // A fan from a new (free) vertex per split face, rather than
    // faces_split_at's pattern: the arms' figures in docs/validation.md were
    // measured with it.
    std::vector<std::array<int, 3>> faces;
    for (int f = 0; f < m.F.rows(); ++f) {
      std::vector<int> poly;
      for (int k = 0; k < 3; ++k) {
        const int a = m.F(f, k), b = m.F(f, (k + 1) % 3);
        poly.push_back(a);
        const auto it = mid.find(edge_key(a, b));
        if (it != mid.end()) poly.push_back(it->second);
      }
      std::size_t c = 0;
      while (c < poly.size() && poly[c] < m.V.rows()) ++c;
      if (c == poly.size()) c = 0;  // no midpoint: the face as it is
      for (std::size_t i = 1; i + 1 < poly.size(); ++i)
        faces.push_back({poly[c], poly[(c + i) % poly.size()], poly[(c + i + 1) % poly.size()]});
    }
    append_split(m, newV, faces);
  }
  return total;
}

}  // namespace

bool map_with_hole_cuts(mesh::TriMesh& sheet, Polycube2D& pc) {
  if (!find_hole_cuts(sheet, pc)) return false;
  split_fixed_chords(sheet, pc.loops, pc.hole_cuts);
  map_to_domain(sheet, pc);
  pc.weights += ", cut from the holes' corners";
  return true;
}

Polycube2D polycube_2d(mesh::TriMesh& sheet, const std::vector<std::vector<int>>& loops,
                       const std::vector<Eigen::Vector3d>& corner_points, bool arms) {
  Polycube2D pc;
  pc.frame = sheet_frame(sheet);
  pc.loops = corner_points.empty() ? automatic_corners(sheet, loops, pc.frame, arms)
                                   : corners_from_points(sheet, loops, corner_points, pc.frame);
  for (const PolycubeLoop& L : pc.loops) pc.lobes += static_cast<int>(L.arms.size());
  refine_hole_corners(sheet, pc.loops);
  // Without their arms, the corners are chosen again as if there were no lobes.
  auto drop_arms = [&](const char* why) {
    pc.loops = automatic_corners(sheet, loops, pc.frame, false);
    pc.arms_dropped = true;
    pc.arms_dropped_reason = why;
  };
  if (pc.lobes > 0 && !arms_apart(pc.loops)) drop_arms("two of them share a neck's corner");
  if (pc.lobes > 0 && !pc.arms_dropped && !find_neck_paths(sheet, pc.loops)) drop_arms("a neck has no path across the sheet");
  if (!pc.arms_dropped && pc.lobes > 0) split_fixed_chords(sheet, pc.loops);
  for (;;) {
    pc.domain = rectilinear_domain(sheet, pc.loops);
    // Harmonic maps onto a domain with holes may fold next to the hole corners;
    // smaller holes (about their centres) leave the map more room.
    for (int attempt = 0; attempt < 4; ++attempt) {
      if (attempt > 0) shrink_holes(pc.domain, 0.8);
      map_to_domain(sheet, pc);
      if (pc.min_jacobian > 0.0 || pc.domain.holes.empty()) break;
    }
    // The arms' reflex corners may fold the map where the rectangle alone does not.
    if (pc.min_jacobian > 0.0 || pc.domain.arms.empty()) break;
    drop_arms("the (u, v) map with them folded");
  }
  // Still folded next to the holes' corners: cut the domain into rectangles
  // from them, each part convex (polycube_hole_cuts.h).
  if (!(pc.min_jacobian > 0.0) && !pc.domain.holes.empty() && pc.domain.arms.empty()) {
    pc.domain = rectilinear_domain(sheet, pc.loops);
    map_with_hole_cuts(sheet, pc);
  }
  if (!(pc.min_jacobian > 0.0)) {
    int flipped = 0;
    for (Eigen::Index f = 0; f < pc.jacobian.size(); ++f) flipped += pc.jacobian(f) <= 0.0;
    // The corners and the cut are the user's to change: bad input, not a failed check of a model.
    throw bad_input("polycube: the (u, v) map of M0trim folds (" + std::to_string(flipped) +
                    " triangles not positively oriented, with cotangent and with mean-value weights); "
                    "give corner points ('midsurface.corners') or other cut loops ('midsurface.cut') in the case file");
  }
  pc.rectangles = domain_rectangles(pc.domain);
  return pc;
}

}  // namespace igaprep::param
