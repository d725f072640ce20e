#include "igaprep/spline/tspline_functions.h"

#include <algorithm>
#include <map>
#include <unordered_map>
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
// end of the domain also at each of the (p - 1) / 2 repeated knots beyond it,
// as the positions in `knots` where each starts (ascending); returns their count.
int windows(const std::vector<TCoord>& knots, TCoord x, TCoord extent, int p, std::array<std::size_t, 8>& starts) {
  const int r = (p - 1) / 2;
  std::array<TCoord, 8> centres{};
  int n = 0;
  centres[static_cast<std::size_t>(n++)] = x;
  for (int g = 1; g <= r && n < 8; ++g) {
    if (x == 0) centres[static_cast<std::size_t>(n++)] = -g * kTScale;
    if (x == extent) centres[static_cast<std::size_t>(n++)] = extent + g * kTScale;
  }
  std::sort(centres.begin(), centres.begin() + n);
  for (int i = 0; i < n; ++i) {
    const auto at = std::lower_bound(knots.begin(), knots.end(), centres[static_cast<std::size_t>(i)]);
    if (at == knots.end() || *at != centres[static_cast<std::size_t>(i)] || at - knots.begin() < r + 1 || knots.end() - at < r + 2)
      throw internal_error("T-spline functions: an anchor off its own ray");
    starts[static_cast<std::size_t>(i)] = static_cast<std::size_t>(at - knots.begin() - (r + 1));
  }
  return n;
}

// A ray's key: the vertex's two other coordinates.
struct LineHash {
  std::size_t operator()(const std::pair<TCoord, TCoord>& l) const {
    return std::hash<TCoord>()(l.first) * 1000003u ^ std::hash<TCoord>()(l.second);
  }
};

// The boxes' corners, each once: packed into one integer of 40 bits per
// coordinate (corners lie in [0, extent], extent < 2^40) to sort fast.
std::vector<Point> mesh_vertices(const TMesh& mesh) {
  using Packed = unsigned __int128;
  std::vector<Packed> corners;
  corners.reserve(8 * mesh.boxes().size());
  for (const TBox& b : mesh.boxes())
    for (int c = 0; c < 8; ++c) {
      Packed key = 0;
      for (int d = 2; d >= 0; --d)
        key = (key << 40) | static_cast<Packed>((c >> d) & 1 ? b.hi[static_cast<std::size_t>(d)] : b.lo[static_cast<std::size_t>(d)]);
      corners.push_back(key);
    }
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  std::vector<Point> vertices(corners.size());
  const Packed mask = (Packed(1) << 40) - 1;
  for (std::size_t i = 0; i < corners.size(); ++i)
    for (int d = 0; d < 3; ++d) vertices[i][static_cast<std::size_t>(d)] = static_cast<TCoord>((corners[i] >> (40 * d)) & mask);
  return vertices;
}

}  // namespace

std::vector<TFunction> tspline_functions(const TMesh& mesh) {
  const std::vector<Point> vertices = mesh_vertices(mesh);
  std::vector<std::pair<std::array<TCoord, 3>, TFunction>> by_anchor;  // keyed (w, v, u): w slowest
  // Vertices on one line along d share their ray: each line is cast once.
  std::array<std::unordered_map<std::pair<TCoord, TCoord>, std::vector<TCoord>, LineHash>, 3> rays;
  by_anchor.reserve(vertices.size());
  for (const Point& a : vertices) {
    std::array<const std::vector<TCoord>*, 3> ray{};
    std::array<std::array<std::size_t, 8>, 3> starts{};
    std::array<int, 3> count{};
    for (std::size_t d = 0; d < 3; ++d) {
      const std::pair<TCoord, TCoord> line{a[(d + 1) % 3], a[(d + 2) % 3]};
      auto it = rays[d].find(line);
      if (it == rays[d].end()) it = rays[d].emplace(line, ray_knots(mesh, a, static_cast<int>(d))).first;
      ray[d] = &it->second;
      count[d] = windows(it->second, a[d], mesh.extent(static_cast<int>(d)), mesh.degrees()[d], starts[d]);
    }
    for (int i = 0; i < count[0]; ++i)
      for (int j = 0; j < count[1]; ++j)
        for (int k = 0; k < count[2]; ++k) {
          TFunction f;
          const std::array<std::size_t, 3> at{{starts[0][static_cast<std::size_t>(i)], starts[1][static_cast<std::size_t>(j)], starts[2][static_cast<std::size_t>(k)]}};
          for (std::size_t d = 0; d < 3; ++d) {
            const auto first = ray[d]->begin() + static_cast<std::ptrdiff_t>(at[d]);
            f.knots[d].assign(first, first + mesh.degrees()[d] + 2);
          }
          by_anchor.emplace_back(std::array<TCoord, 3>{{f.anchor(2), f.anchor(1), f.anchor(0)}}, std::move(f));
        }
  }
  // Ordered by anchor; an anchor reached from two vertices is one function.
  std::stable_sort(by_anchor.begin(), by_anchor.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<TFunction> out;
  out.reserve(by_anchor.size());
  for (std::size_t i = 0; i < by_anchor.size(); ++i)
    if (i == 0 || by_anchor[i].first != by_anchor[i - 1].first) out.push_back(std::move(by_anchor[i].second));
  return out;
}

bool knot_vectors_overlap(const std::vector<TCoord>& a, const std::vector<TCoord>& b) {
  const TCoord lo = std::max(a.front(), b.front()), hi = std::min(a.back(), b.back());
  auto first_a = std::lower_bound(a.begin(), a.end(), lo), first_b = std::lower_bound(b.begin(), b.end(), lo);
  const auto last_a = std::upper_bound(a.begin(), a.end(), hi), last_b = std::upper_bound(b.begin(), b.end(), hi);
  return std::equal(first_a, last_a, first_b, last_b);
}

KnotVectorIds knot_vector_ids(const std::vector<TFunction>& functions, int d) {
  KnotVectorIds out;
  std::map<std::vector<TCoord>, int> ids;
  out.of_function.reserve(functions.size());
  for (const TFunction& f : functions) {
    const std::vector<TCoord>& k = f.knots[static_cast<std::size_t>(d)];
    const auto [it, added] = ids.emplace(k, static_cast<int>(out.vectors.size()));
    if (added) out.vectors.push_back(k);
    out.of_function.push_back(it->second);
  }
  return out;
}

namespace {

// Whether two knot vectors of one direction (knot_vector_ids) differ and
// overlap: asked of many pairs of functions, computed once per pair of vectors.
class KnotVectorRelations {
 public:
  explicit KnotVectorRelations(const std::vector<std::vector<TCoord>>& vectors)
      : vectors_(vectors), known_(vectors.size() * vectors.size(), -1) {}
  bool partial(int a, int b) {
    if (a == b) return false;
    signed char& k = known_[static_cast<std::size_t>(a) * vectors_.size() + static_cast<std::size_t>(b)];
    if (k < 0) k = knot_vectors_overlap(vectors_[static_cast<std::size_t>(a)], vectors_[static_cast<std::size_t>(b)]) ? 1 : 0;
    return k == 1;
  }

 private:
  const std::vector<std::vector<TCoord>>& vectors_;
  std::vector<signed char> known_;
};

}  // namespace

std::optional<std::pair<int, int>> dual_compatibility_violation(const TMesh& mesh,
                                                                const std::vector<TFunction>& functions) {
  // Supports as flat rows (lo u, hi u, lo v, hi v, lo w, hi w) with the
  // knot vectors' ids, sorted by lo u and swept in u.
  struct Row {
    std::array<TCoord, 6> support;
    std::array<int, 3> knots;
    int function;
  };
  const std::array<KnotVectorIds, 3> ids{{knot_vector_ids(functions, 0), knot_vector_ids(functions, 1), knot_vector_ids(functions, 2)}};
  std::array<KnotVectorRelations, 3> relations{{KnotVectorRelations(ids[0].vectors), KnotVectorRelations(ids[1].vectors),
                                                KnotVectorRelations(ids[2].vectors)}};
  std::vector<Row> rows(functions.size());
  for (std::size_t f = 0; f < functions.size(); ++f)
    rows[f] = {functions[f].support(mesh), {{ids[0].of_function[f], ids[1].of_function[f], ids[2].of_function[f]}}, static_cast<int>(f)};
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.support[0] < b.support[0]; });
  for (std::size_t x = 0; x < rows.size(); ++x) {
    const std::array<TCoord, 6>& sf = rows[x].support;
    for (std::size_t y = x + 1; y < rows.size(); ++y) {
      const std::array<TCoord, 6>& sg = rows[y].support;
      if (sg[0] >= sf[1]) break;
      if (!(sg[2] < sf[3] && sf[2] < sg[3] && sg[4] < sf[5] && sf[4] < sg[5])) continue;
      bool partial = false;
      for (std::size_t d = 0; d < 3 && !partial; ++d) partial = relations[d].partial(rows[x].knots[d], rows[y].knots[d]);
      if (!partial) return std::make_pair(rows[x].function, rows[y].function);
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
