#pragma once
// Private to spline/: the NURCC refinement rules as sparse weights
// (Sederberg et al. 2003, section 7) and the cage topology they read (a
// vertex's star and its spokes in cyclic order); shared by the refinement
// (tnurcc_refine.cpp) and the limit positions (tnurcc_vertex_limits.cpp).
#include <Eigen/Core>
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "igaprep/core/error.h"
#include "igaprep/spline/tnurcc_cage.h"
#include "igaprep/spline/tnurcc_limit.h"

namespace igaprep::spline::detail {

inline bool sharp(const CageEdge& e) { return e.sharpness > 0.0 || e.faces[1] < 0; }  // a crease or the border

struct VertexStar {
  std::vector<int> edges, faces;
};

inline std::vector<VertexStar> stars(const Cage& cage) {
  std::vector<VertexStar> out(cage.points.rows());
  for (size_t e = 0; e < cage.edges.size(); ++e)
    for (int v : cage.edges[e].vertices) out[v].edges.push_back(static_cast<int>(e));
  for (size_t f = 0; f < cage.faces.size(); ++f)
    for (int v : cage.faces[f]) out[v].faces.push_back(static_cast<int>(f));
  return out;
}

inline int other_end(const CageEdge& e, int v) { return e.vertices[0] == v ? e.vertices[1] : e.vertices[0]; }

// The vertices of v's creases (crease and border edges), and whether v is a corner.
struct CreaseStar {
  std::vector<int> ends;
  bool corner = false;
};
inline CreaseStar crease_star(const Cage& cage, const VertexStar& star, int v) {
  CreaseStar c;
  bool border = false;
  for (int e : star.edges) {
    if (sharp(cage.edges[e])) c.ends.push_back(other_end(cage.edges[e], v));
    border = border || cage.edges[e].faces[1] < 0;
  }
  c.corner = c.ends.size() >= 3 || (border && star.edges.size() == 2);
  return c;
}

// The edges around a vertex in cyclic order, face k lying between spokes k
// and k + 1 (faces are oriented alike, so each face's edge into the vertex
// is the next face's edge out of it). `closed` is false for a vertex on the
// cage's border (an open fan), whose order is then not used.
struct Spokes {
  std::vector<int> edges, faces;
  bool closed = false;
};

inline Spokes spokes(const Cage& cage, const VertexStar& star, int v) {
  Spokes s;
  if (star.faces.empty()) return s;
  int f = star.faces[0];
  for (size_t step = 0; step < star.faces.size(); ++step) {
    int k = 0;
    while (cage.faces[f][k] != v) ++k;
    s.edges.push_back(cage.face_edges[f][k]);
    s.faces.push_back(f);
    const CageEdge& in = cage.edges[cage.face_edges[f][(k + 3) % 4]];
    const int next = in.faces[0] == f ? in.faces[1] : in.faces[0];
    if (next < 0) return s;  // the border: an open fan
    if (next == star.faces[0]) {
      s.closed = s.faces.size() == star.faces.size();
      return s;
    }
    f = next;
  }
  return s;
}

// A new point as weights of the parent's points (repeats allowed: summed).
using Stencil = std::vector<std::pair<int, double>>;

inline void add(Stencil& into, const Stencil& s, double w) {
  for (const auto& [i, x] : s) into.emplace_back(i, w * x);
}
inline void scale(Stencil& s, double w) {
  for (auto& entry : s) entry.second *= w;
}

inline StencilMatrix stencil_rows(const std::vector<Stencil>& rows, int columns) {
  std::vector<Eigen::Triplet<double>> t;
  for (size_t r = 0; r < rows.size(); ++r)
    for (const auto& [c, w] : rows[r]) t.emplace_back(static_cast<int>(r), c, w);
  StencilMatrix m(static_cast<int>(rows.size()), columns);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

// The NURCC rules (Sederberg et al. 2003, section 7, from cubic NURSS with
// opposite edges of each face equal): each derived from non-uniform cubic
// B-spline knot insertion at the middle of every interval (blossoms), and
// around an extraordinary vertex by the same weights over its spokes.
class NurccRules {
 public:
  explicit NurccRules(const Cage& cage) : c_(cage), star_(stars(cage)) {
    spokes_.reserve(star_.size());
    for (int v = 0; v < static_cast<int>(star_.size()); ++v) spokes_.push_back(spokes(cage, star_[v], v));
  }

  // Cubic B-spline knot insertion in [u_a, u_b] (interval q) of a row with
  // intervals p before a and r after b: the new point between a and b.
  static Stencil edge_rule(int a, int b, double p, double q, double r) {
    const double wa = (q + 2.0 * r) / (2.0 * (p + q + r));
    return {{a, wa}, {b, 1.0 - wa}};
  }

  // The interval of the faces across edge k of face f, in the direction of
  // f's edges k + 1 and k + 3 (the same in both by the opposite-edge rule);
  // f's own when edge k is on the border.
  double across(int f, int k) const {
    const CageEdge& e = c_.edges[c_.face_edges[f][k]];
    const int g = e.faces[0] == f ? e.faces[1] : e.faces[0];
    if (g < 0) return c_.edges[c_.face_edges[f][(k + 1) % 4]].interval;
    int j = 0;
    while (c_.face_edges[g][j] != c_.face_edges[f][k]) ++j;
    return c_.edges[c_.face_edges[g][(j + 1) % 4]].interval;
  }

  // Face f = (v0, v1, v2, v3): s along edge 0 (v0 -> v1), t along edge 3 (v0 -> v3).
  Stencil face_point(int f) const {
    const auto& v = c_.faces[f];
    const double qs = c_.edges[c_.face_edges[f][0]].interval, qt = c_.edges[c_.face_edges[f][3]].interval;
    const double ps = across(f, 3), rs = across(f, 1), pt = across(f, 0), rt = across(f, 2);
    const double s0 = (0.5 * qs + rs) / (ps + qs + rs), s1 = 1.0 - s0;
    const double t0 = (0.5 * qt + rt) / (pt + qt + rt), t1 = 1.0 - t0;
    return {{v[0], t0 * s0}, {v[1], t0 * s1}, {v[3], t1 * s0}, {v[2], t1 * s1}};
  }

  // The interval that continues edge e beyond vertex v: along a crease the
  // vertex's other crease edge; at a smooth vertex the mean of the spokes
  // two steps either way (the opposite spoke at valence 4); else e's own.
  double continuation(int e, int v) const {
    const CageEdge& edge = c_.edges[e];
    if (sharp(edge)) {
      std::vector<int> other;
      for (int x : star_[v].edges)
        if (x != e && sharp(c_.edges[x])) other.push_back(x);
      return other.size() == 1 ? c_.edges[other[0]].interval : edge.interval;
    }
    const Spokes& s = spokes_[v];
    const int n = static_cast<int>(s.edges.size());
    if (!s.closed || n < 3) return edge.interval;
    const int i = static_cast<int>(std::find(s.edges.begin(), s.edges.end(), e) - s.edges.begin());
    return 0.5 * (c_.edges[s.edges[(i + 2) % n]].interval + c_.edges[s.edges[(i + n - 2) % n]].interval);
  }

  // The 1-D knot insertion along edge e's own row (M in the paper).
  Stencil row_point(int e) const {
    const CageEdge& edge = c_.edges[e];
    const int a = edge.vertices[0], b = edge.vertices[1];
    return edge_rule(a, b, continuation(e, a), edge.interval, continuation(e, b));
  }

  // The interval of face f across edge e (its edges at e's ends).
  double width(int f, int e) const {
    int k = 0;
    while (c_.face_edges[f][k] != e) ++k;
    return c_.edges[c_.face_edges[f][(k + 1) % 4]].interval;
  }

  Stencil edge_point(int e, const std::vector<Stencil>& face_points) const {
    const CageEdge& edge = c_.edges[e];
    Stencil out = row_point(e);
    if (sharp(edge)) return out;
    scale(out, 0.5);
    const int f1 = edge.faces[0], f2 = edge.faces[1];
    const double w1 = width(f1, e), w2 = width(f2, e);
    add(out, face_points[f1], 0.5 * w2 / (w1 + w2));
    add(out, face_points[f2], 0.5 * w1 / (w1 + w2));
    return out;
  }

  Stencil vertex_point(int v, const std::vector<Stencil>& edge_points, const std::vector<Stencil>& face_points) const {
    const CreaseStar cs = crease_star(c_, star_[v], v);
    if (cs.corner) return {{v, 1.0}};
    Stencil out{{v, 0.5}};
    if (cs.ends.size() == 2) {
      std::vector<int> creases;
      for (int x : star_[v].edges)
        if (sharp(c_.edges[x])) creases.push_back(x);
      const double da = c_.edges[creases[0]].interval, db = c_.edges[creases[1]].interval;
      add(out, edge_points[creases[0]], db / (2.0 * (da + db)));
      add(out, edge_points[creases[1]], da / (2.0 * (da + db)));
      return out;
    }
    const Spokes& s = spokes_[v];
    const int n = static_cast<int>(s.edges.size());
    if (!s.closed) throw internal_error("T-NURCC refinement: a smooth vertex on the border");
    auto h = [&](int i) { return c_.edges[s.edges[((i % n) + n) % n]].interval; };
    std::vector<double> m(n), f(n);
    double m_weight = 0.0, f_weight = 0.0;
    for (int i = 0; i < n; ++i) {
      m[i] = 0.5 * (h(i - 1) + h(i + 1)) * (h(i - 2) + h(i + 2));
      f[i] = h(i - 1) * h(i + 2);
      m_weight += m[i];
      f_weight += f[i];
    }
    out = {{v, (n - 3.0) / n}};
    for (int i = 0; i < n; ++i) {
      add(out, row_point(s.edges[i]), 2.0 * m[i] / (m_weight * n));
      add(out, face_points[s.faces[i]], f[i] / (f_weight * n));
    }
    return out;
  }

 const Spokes& spokes_of(int v) const { return spokes_[v]; }
  const VertexStar& star_of(int v) const { return star_[v]; }

 private:
  const Cage& c_;
  std::vector<VertexStar> star_;
  std::vector<Spokes> spokes_;
};

// What the rules here cover: opposite edges of each face equal, every edge
// smooth or infinitely sharp.
inline void require_nurcc(const Cage& cage) {
  if (!opposite_edge_violations(cage).empty())
    throw bad_input("T-NURCC refinement: opposite edges of a face carry different knot intervals");
  for (const auto& e : cage.edges)
    if (e.sharpness > 0.0 && e.sharpness < kInfiniteSharpness)
      throw bad_input("T-NURCC refinement: edge (" + std::to_string(e.vertices[0]) + ", " +
                      std::to_string(e.vertices[1]) + ") is semi-sharp; only smooth and infinitely sharp edges are");
}

}  // namespace igaprep::spline::detail
