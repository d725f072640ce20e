#include "igaprep/spline/tspline_functions.h"

#include <algorithm>
#include <map>
#include <string>

#include "igaprep/core/error.h"

namespace igaprep::spline {

namespace {

using Point = std::array<TCoord, 3>;

// The elements of direction d whose closed span holds index coordinate x.
std::pair<int, int> elements_holding(TCoord x, int count) {
  const int last = static_cast<int>(std::min<TCoord>(count - 1, x / kTScale));
  const int first = x % kTScale == 0 && x > 0 ? last - (x / kTScale <= count - 1 ? 1 : 0) : last;
  return {std::max(0, first), last};
}

// The knots a ray from `a` along d crosses: the d-faces of every box whose
// closure holds the ray (its other coordinates inside the box's closed
// ranges), with the repeated end knots numbered on beyond the domain.
std::vector<TCoord> ray_knots(const TMesh& mesh, const Point& a, int d) {
  const int d1 = (d + 1) % 3, d2 = (d + 2) % 3;
  const auto [f1, l1] = elements_holding(a[static_cast<std::size_t>(d1)], mesh.elements()[static_cast<std::size_t>(d1)]);
  const auto [f2, l2] = elements_holding(a[static_cast<std::size_t>(d2)], mesh.elements()[static_cast<std::size_t>(d2)]);
  const int p = mesh.degrees()[static_cast<std::size_t>(d)];
  std::vector<TCoord> knots;
  for (int j = 1; j <= p; ++j) knots.push_back(-j * kTScale);
  for (int j = 1; j <= p; ++j) knots.push_back(mesh.extent(d) + j * kTScale);
  std::array<int, 3> e{};
  for (e[static_cast<std::size_t>(d2)] = f2; e[static_cast<std::size_t>(d2)] <= l2; ++e[static_cast<std::size_t>(d2)])
    for (e[static_cast<std::size_t>(d1)] = f1; e[static_cast<std::size_t>(d1)] <= l1; ++e[static_cast<std::size_t>(d1)])
      for (e[static_cast<std::size_t>(d)] = 0; e[static_cast<std::size_t>(d)] < mesh.elements()[static_cast<std::size_t>(d)];
           ++e[static_cast<std::size_t>(d)]) {
        const int element = e[0] + mesh.elements()[0] * (e[1] + mesh.elements()[1] * e[2]);
        for (const int b : mesh.boxes_in(element)) {
          const TBox& q = mesh.boxes()[static_cast<std::size_t>(b)];
          const bool holds = q.lo[static_cast<std::size_t>(d1)] <= a[static_cast<std::size_t>(d1)] &&
                             a[static_cast<std::size_t>(d1)] <= q.hi[static_cast<std::size_t>(d1)] &&
                             q.lo[static_cast<std::size_t>(d2)] <= a[static_cast<std::size_t>(d2)] &&
                             a[static_cast<std::size_t>(d2)] <= q.hi[static_cast<std::size_t>(d2)];
          if (!holds) continue;
          knots.push_back(q.lo[static_cast<std::size_t>(d)]);
          knots.push_back(q.hi[static_cast<std::size_t>(d)]);
        }
      }
  std::sort(knots.begin(), knots.end());
  knots.erase(std::unique(knots.begin(), knots.end()), knots.end());
  return knots;
}

// The windows of p + 2 knots centred at the vertex's coordinate, and at an
// end of the domain also at each of the (p - 1) / 2 repeated knots beyond it.
std::vector<std::vector<TCoord>> windows(const std::vector<TCoord>& knots, TCoord x, TCoord extent, int p) {
  const int r = (p - 1) / 2;
  std::vector<TCoord> centres{x};
  for (int g = 1; g <= r; ++g) {
    if (x == 0) centres.push_back(-g * kTScale);
    if (x == extent) centres.push_back(extent + g * kTScale);
  }
  std::sort(centres.begin(), centres.end());
  std::vector<std::vector<TCoord>> out;
  for (const TCoord c : centres) {
    const auto at = std::lower_bound(knots.begin(), knots.end(), c);
    if (at == knots.end() || *at != c || at - knots.begin() < r + 1 || knots.end() - at < r + 2)
      throw internal_error("T-spline functions: an anchor off its own ray");
    out.emplace_back(at - (r + 1), at + (r + 2));
  }
  return out;
}

}  // namespace

std::vector<TFunction> tspline_functions(const TMesh& mesh) {
  std::vector<Point> vertices;
  for (const TBox& b : mesh.boxes())
    for (int c = 0; c < 8; ++c)
      vertices.push_back({{(c & 1) ? b.hi[0] : b.lo[0], (c & 2) ? b.hi[1] : b.lo[1], (c & 4) ? b.hi[2] : b.lo[2]}});
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  std::map<std::array<TCoord, 3>, TFunction> by_anchor;  // keyed (w, v, u): w slowest
  for (const Point& a : vertices) {
    std::array<std::vector<std::vector<TCoord>>, 3> per_dir;
    for (int d = 0; d < 3; ++d)
      per_dir[static_cast<std::size_t>(d)] = windows(ray_knots(mesh, a, d), a[static_cast<std::size_t>(d)], mesh.extent(d),
                                                     mesh.degrees()[static_cast<std::size_t>(d)]);
    for (const auto& ku : per_dir[0])
      for (const auto& kv : per_dir[1])
        for (const auto& kw : per_dir[2]) {
          TFunction f;
          f.knots = {{ku, kv, kw}};
          by_anchor.emplace(std::array<TCoord, 3>{{f.anchor(2), f.anchor(1), f.anchor(0)}}, std::move(f));
        }
  }
  std::vector<TFunction> out;
  out.reserve(by_anchor.size());
  for (auto& [key, f] : by_anchor) out.push_back(std::move(f));
  return out;
}

bool knot_vectors_overlap(const std::vector<TCoord>& a, const std::vector<TCoord>& b) {
  const TCoord lo = std::max(a.front(), b.front()), hi = std::min(a.back(), b.back());
  auto first_a = std::lower_bound(a.begin(), a.end(), lo), first_b = std::lower_bound(b.begin(), b.end(), lo);
  const auto last_a = std::upper_bound(a.begin(), a.end(), hi), last_b = std::upper_bound(b.begin(), b.end(), hi);
  return std::equal(first_a, last_a, first_b, last_b);
}

std::optional<std::pair<int, int>> dual_compatibility_violation(const TMesh& mesh,
                                                                const std::vector<TFunction>& functions) {
  // Supports as flat rows (lo u, hi u, lo v, hi v, lo w, hi w), swept in u.
  std::vector<std::array<TCoord, 6>> support(functions.size());
  for (std::size_t f = 0; f < functions.size(); ++f)
    for (int d = 0; d < 3; ++d) {
      support[f][static_cast<std::size_t>(2 * d)] = functions[f].support_lo(d);
      support[f][static_cast<std::size_t>(2 * d + 1)] = functions[f].support_hi(d, mesh);
    }
  std::vector<int> order(functions.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return support[static_cast<std::size_t>(a)][0] < support[static_cast<std::size_t>(b)][0]; });
  for (std::size_t x = 0; x < order.size(); ++x) {
    const std::array<TCoord, 6>& sf = support[static_cast<std::size_t>(order[x])];
    for (std::size_t y = x + 1; y < order.size(); ++y) {
      const std::array<TCoord, 6>& sg = support[static_cast<std::size_t>(order[y])];
      if (sg[0] >= sf[1]) break;
      if (!(sg[2] < sf[3] && sf[2] < sg[3] && sg[4] < sf[5] && sf[4] < sg[5])) continue;
      const TFunction& f = functions[static_cast<std::size_t>(order[x])];
      const TFunction& g = functions[static_cast<std::size_t>(order[y])];
      bool partial = false;
      for (std::size_t d = 0; d < 3 && !partial; ++d)
        partial = f.knots[d] != g.knots[d] && knot_vectors_overlap(f.knots[d], g.knots[d]);
      if (!partial) return std::make_pair(order[x], order[y]);
    }
  }
  return std::nullopt;
}

namespace {

std::string describe(const TFunction& f) {
  std::string s = "anchor (";
  for (int d = 0; d < 3; ++d) s += (d ? ", " : "") + std::to_string(static_cast<double>(f.anchor(d)) / kTScale);
  s += "), knots";
  for (std::size_t d = 0; d < 3; ++d) {
    s += " [";
    for (std::size_t k = 0; k < f.knots[d].size(); ++k) s += (k ? " " : "") + std::to_string(static_cast<double>(f.knots[d][k]) / kTScale);
    s += "]";
  }
  return s;
}

}  // namespace

void check_analysis_suitable(const TMesh& mesh) {
  const std::vector<TFunction> functions = tspline_functions(mesh);
  if (const auto bad = dual_compatibility_violation(mesh, functions))
    throw bad_input("T-mesh is not analysis-suitable: the functions at " + describe(functions[static_cast<std::size_t>(bad->first)]) +
                    " and at " + describe(functions[static_cast<std::size_t>(bad->second)]) +
                    " overlap but share no direction with overlapping, different knot vectors (index space)");
}

}  // namespace igaprep::spline
