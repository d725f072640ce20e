#include "igaprep/param/sheet_lobes.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include <Eigen/Geometry>

#include "edge_graph.h"

namespace igaprep::param {
namespace {

// A pair of boundary samples and the arc forward from the first to the second.
struct NeckCandidate {
  int a = 0, b = 0;        // sample indices
  double arc = 0.0, neck = 0.0, area = 0.0, modulus = 0.0;
};

struct LobeSearch {
  const mesh::TriMesh& sheet;
  const std::vector<int>& loop;
  std::vector<double> s;          // arc length at each loop position (size n + 1)
  std::vector<int> sample;        // loop positions of the samples
  std::vector<detail::ShortestPaths> paths;  // from each sample
  std::vector<char> foreign;      // vertices of the other loops
  std::vector<std::vector<int>> neighbours;
  Eigen::VectorXd face_area;
  std::vector<int> stamp;         // flood-fill marks, by epoch
  int epoch = 0;

  // Arc length along the loop at sample k, and forward from sample a to b.
  double at(int k) const { return s[static_cast<std::size_t>(sample[static_cast<std::size_t>(k)])]; }
  double arc(int a, int b) const { return std::fmod(at(b) - at(a) + s.back(), s.back()); }
  int vertex(int k) const { return loop[static_cast<std::size_t>(sample[static_cast<std::size_t>(k)])]; }

  // The loop's vertex nearest to arc length x from its start (any x: taken round the loop).
  Eigen::Vector3d point_at(double x) const {
    const double total = s.back();
    x = std::fmod(std::fmod(x, total) + total, total);
    const auto it = std::lower_bound(s.begin(), s.end(), x);
    std::size_t p = static_cast<std::size_t>(it - s.begin());
    if (p > 0 && (p == s.size() || x - s[p - 1] < s[p] - x)) --p;
    return sheet.V.row(loop[p % loop.size()]).transpose();
  }

  // Distance between the boundary points one neck width outside a neck's ends.
  double beyond(int a, int b, double neck) const {
    return (point_at(at(a) - neck) - point_at(at(b) + neck)).norm();
  }

  // Area of the part that the shortest path between the two samples cuts off
  // on the side of the arc forward from a; negative when that part holds a
  // vertex of another loop (a hole).
  double cut_area(int a, int b) {
    const std::vector<int> path = detail::path_to(paths[static_cast<std::size_t>(a)], vertex(b));
    const int cut = ++epoch, inside = ++epoch;
    for (int v : path) stamp[static_cast<std::size_t>(v)] = cut;
    const std::size_t n = loop.size();
    std::size_t p = static_cast<std::size_t>(sample[static_cast<std::size_t>(a)]);
    do p = (p + 1) % n;
    while (stamp[static_cast<std::size_t>(loop[p])] == cut && p != static_cast<std::size_t>(sample[static_cast<std::size_t>(b)]));
    if (stamp[static_cast<std::size_t>(loop[p])] == cut) return 0.0;  // the arc is the path itself
    std::vector<int> stack{loop[p]};
    stamp[static_cast<std::size_t>(loop[p])] = inside;
    bool hole = false;
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      hole = hole || foreign[static_cast<std::size_t>(v)];
      for (int w : neighbours[static_cast<std::size_t>(v)])
        if (stamp[static_cast<std::size_t>(w)] != cut && stamp[static_cast<std::size_t>(w)] != inside) {
          stamp[static_cast<std::size_t>(w)] = inside;
          stack.push_back(w);
        }
    }
    if (hole) return -1.0;
    double area = 0.0;
    for (Eigen::Index f = 0; f < sheet.F.rows(); ++f) {
      int in = 0, on = 0;
      for (int k = 0; k < 3; ++k) {
        const int m = stamp[static_cast<std::size_t>(sheet.F(f, k))];
        in += m == inside;
        on += m == cut;
      }
      if (in > 0 && in + on == 3) area += face_area(f);
    }
    return area;
  }
};

// Whether two arcs share a loop position. Arcs that only touch (one's end is
// the other's start) share one: two arms need a loop edge between them. The
// arcs' ends are compared by sample, not by arc length, which rounding can
// put a hair apart.
bool overlaps(const LobeSearch& q, const NeckCandidate& x, const NeckCandidate& y) {
  if (x.a == y.a || x.a == y.b || x.b == y.a || x.b == y.b) return true;
  // Loop positions covered by each arc, as intervals on the unrolled loop.
  const double total = q.s.back();
  const double xa = q.at(x.a), ya = q.at(y.a);
  for (const double shift : {-total, 0.0, total}) {
    const double lo = ya + shift, hi = ya + shift + y.arc;
    if (xa <= hi && lo <= xa + x.arc) return true;
  }
  return false;
}

bool contains(const LobeSearch& q, const NeckCandidate& outer, const NeckCandidate& inner) {
  const double total = q.s.back();
  const double offset = std::fmod(q.at(inner.a) - q.at(outer.a) + total, total);
  return offset + inner.arc <= outer.arc && inner.arc < outer.arc;
}

}  // namespace

std::vector<SheetLobe> find_lobes(const mesh::TriMesh& sheet, const std::vector<int>& loop,
                                  const std::vector<std::vector<int>>& other_loops, const LobeOptions& o) {
  const std::size_t n = loop.size();
  if (n < 8 || sheet.F.rows() == 0) return {};
  LobeSearch q{sheet, loop, {}, {}, {}, {}, {}, {}, {}, 0};
  q.s.assign(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    q.s[i + 1] = q.s[i] + (sheet.V.row(loop[(i + 1) % n]) - sheet.V.row(loop[i])).norm();
  const int ns = static_cast<int>(std::min<std::size_t>(n, static_cast<std::size_t>(o.samples)));
  for (int k = 0; k < ns; ++k) q.sample.push_back(static_cast<int>(static_cast<std::size_t>(k) * n / static_cast<std::size_t>(ns)));
  const detail::EdgeGraph graph = detail::edge_graph(sheet);
  q.neighbours.resize(graph.size());
  for (std::size_t v = 0; v < graph.size(); ++v)
    for (const auto& [w, len] : graph[v]) q.neighbours[v].push_back(w);
  q.foreign.assign(graph.size(), 0);
  for (const auto& other : other_loops)
    for (int v : other) q.foreign[static_cast<std::size_t>(v)] = 1;
  q.stamp.assign(graph.size(), 0);
  q.face_area.resize(sheet.F.rows());
  double total_area = 0.0;
  for (Eigen::Index f = 0; f < sheet.F.rows(); ++f) {
    const Eigen::Vector3d a = sheet.V.row(sheet.F(f, 0)), b = sheet.V.row(sheet.F(f, 1)), c = sheet.V.row(sheet.F(f, 2));
    q.face_area(f) = 0.5 * (b - a).cross(c - a).norm();
    total_area += q.face_area(f);
  }
  // Each sample's shortest-path tree; of its distances only those to the
  // other samples are kept (the trees of a large sheet are large).
  std::vector<std::vector<double>> between(static_cast<std::size_t>(ns), std::vector<double>(static_cast<std::size_t>(ns)));
  for (int k = 0; k < ns; ++k) {
    q.paths.push_back(detail::shortest_paths(graph, q.vertex(k)));
    for (int j = 0; j < ns; ++j)
      between[static_cast<std::size_t>(k)][static_cast<std::size_t>(j)] = q.paths.back().dist[static_cast<std::size_t>(q.vertex(j))];
    q.paths.back().dist = {};
  }

  // Candidates: a long arc between two close ends, the lobe the smaller part.
  std::vector<NeckCandidate> candidates;
  for (int a = 0; a < ns; ++a)
    for (int b = 0; b < ns; ++b) {
      if (a == b) continue;
      NeckCandidate c{a, b, q.arc(a, b), (sheet.V.row(q.vertex(a)) - sheet.V.row(q.vertex(b))).norm()};
      const double detour = between[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)];
      if (c.arc > 0.5 * q.s.back() || !(c.neck > 0.0) || c.arc < 3.0 * c.neck || detour > o.max_detour * c.neck ||
          q.beyond(a, b, c.neck) < o.min_widening * c.neck)
        continue;
      candidates.push_back(c);
    }
  // The most promising first (long arcs for their necks), a bounded number.
  std::sort(candidates.begin(), candidates.end(), [](const NeckCandidate& x, const NeckCandidate& y) {
    return std::make_tuple(x.arc / x.neck, x.a, x.b) > std::make_tuple(y.arc / y.neck, y.a, y.b);
  });
  if (candidates.size() > 1500) candidates.resize(1500);
  std::vector<NeckCandidate> scored;
  for (NeckCandidate c : candidates) {
    c.area = q.cut_area(c.a, c.b);
    c.modulus = c.area / (c.neck * c.neck);
    if (c.area > 0.0 && c.area <= o.max_area_share * total_area) scored.push_back(c);
  }
  std::stable_sort(scored.begin(), scored.end(),
                   [](const NeckCandidate& x, const NeckCandidate& y) { return x.modulus > y.modulus; });

  // Greedy by modulus, arcs apart; each lobe moved out along its taper.
  std::vector<NeckCandidate> chosen;
  auto apart = [&](const NeckCandidate& c, std::size_t skip) {
    for (std::size_t i = 0; i < chosen.size(); ++i)
      if (i != skip && overlaps(q, c, chosen[i])) return false;
    return true;
  };
  for (const NeckCandidate& c : scored) {
    if (c.modulus < o.min_modulus || !apart(c, chosen.size())) continue;
    NeckCandidate lobe = c;
    for (bool moved = true; moved;) {
      moved = false;
      const NeckCandidate* next = nullptr;
      for (const NeckCandidate& wider : scored)
        if (wider.modulus >= std::max(o.min_modulus, o.keep_share * c.modulus) && wider.neck <= o.taper * lobe.neck &&
            contains(q, wider, lobe) && apart(wider, chosen.size()) && (!next || wider.arc > next->arc))
          next = &wider;
      if (next) lobe = *next, moved = true;
    }
    chosen.push_back(lobe);
  }
  double lobes_area = 0.0;
  for (const NeckCandidate& c : chosen) lobes_area += c.area;
  if (lobes_area > o.max_total_share * total_area) return {};
  std::vector<SheetLobe> out;
  for (const NeckCandidate& c : chosen)
    out.push_back({q.sample[static_cast<std::size_t>(c.a)], q.sample[static_cast<std::size_t>(c.b)], c.neck, c.area, c.modulus});
  std::sort(out.begin(), out.end(), [](const SheetLobe& x, const SheetLobe& y) { return x.start < y.start; });
  return out;
}

}  // namespace igaprep::param
