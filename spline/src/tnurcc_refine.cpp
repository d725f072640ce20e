#include "igaprep/spline/tnurcc_refine.h"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <map>

#include "igaprep/core/error.h"

namespace igaprep::spline {
namespace {

bool sharp(const CageEdge& e) { return e.sharpness > 0.0 || e.faces[1] < 0; }  // a crease or the border

struct VertexStar {
  std::vector<int> edges, faces;
};

std::vector<VertexStar> stars(const Cage& cage) {
  std::vector<VertexStar> out(cage.points.rows());
  for (size_t e = 0; e < cage.edges.size(); ++e)
    for (int v : cage.edges[e].vertices) out[v].edges.push_back(static_cast<int>(e));
  for (size_t f = 0; f < cage.faces.size(); ++f)
    for (int v : cage.faces[f]) out[v].faces.push_back(static_cast<int>(f));
  return out;
}

int other_end(const CageEdge& e, int v) { return e.vertices[0] == v ? e.vertices[1] : e.vertices[0]; }

// The vertices of v's creases (crease and border edges), and whether v is a corner.
struct CreaseStar {
  std::vector<int> ends;
  bool corner = false;
};
CreaseStar crease_star(const Cage& cage, const VertexStar& star, int v) {
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

Spokes spokes(const Cage& cage, const VertexStar& star, int v) {
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

void add(Stencil& into, const Stencil& s, double w) {
  for (const auto& [i, x] : s) into.emplace_back(i, w * x);
}
void scale(Stencil& s, double w) {
  for (auto& entry : s) entry.second *= w;
}

StencilMatrix stencil_rows(const std::vector<Stencil>& rows, int columns) {
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
void require_nurcc(const Cage& cage) {
  if (!opposite_edge_violations(cage).empty())
    throw bad_input("T-NURCC refinement: opposite edges of a face carry different knot intervals");
  for (const auto& e : cage.edges)
    if (e.sharpness > 0.0 && e.sharpness < kInfiniteSharpness)
      throw bad_input("T-NURCC refinement: edge (" + std::to_string(e.vertices[0]) + ", " +
                      std::to_string(e.vertices[1]) + ") is semi-sharp; only smooth and infinitely sharp edges are");
}

// The cubic B-spline's value at the knot between intervals a (before the
// point) and b (after it), pa beyond the point before and rb beyond the
// point after: the weights of (point before, the point, point after), by
// blossoms (f(u, u, u) from the two points' neighbours).
std::array<double, 3> limit_mask(double pa, double a, double b, double rb) {
  const double before = (b / (a + b)) * (b / (pa + a + b)), after = (a / (a + b)) * (a / (a + b + rb));
  return {{before, 1.0 - before - after, after}};
}

// A valence-4 smooth vertex: the tensor product of the masks along its two
// lines of spokes (0, 2) and (1, 3); face i's far corner takes the product
// of spoke i's and spoke i + 1's end weights.
Stencil regular_limit(const Cage& c, const NurccRules& rules, int v) {
  const Spokes& s = rules.spokes_of(v);
  std::array<int, 4> end{};
  std::array<double, 4> h{}, beyond{};
  for (int i = 0; i < 4; ++i) {
    end[i] = other_end(c.edges[s.edges[i]], v);
    h[i] = c.edges[s.edges[i]].interval;
    beyond[i] = rules.continuation(s.edges[i], end[i]);
  }
  const auto ms = limit_mask(beyond[2], h[2], h[0], beyond[0]), mt = limit_mask(beyond[3], h[3], h[1], beyond[1]);
  const std::array<double, 4> w{{ms[2], mt[2], ms[0], mt[0]}};  // each spoke's end weight
  Stencil out{{v, ms[1] * mt[1]}};
  for (int i = 0; i < 4; ++i) {
    const double across = i % 2 == 0 ? mt[1] : ms[1];
    out.emplace_back(end[i], w[i] * across);
    const auto& f = c.faces[s.faces[i]];
    int k = 0;
    while (f[k] != v) ++k;
    out.emplace_back(f[(k + 2) % 4], w[i] * w[(i + 1) % 4]);
  }
  return out;
}

// A crease vertex: the mask along its two crease edges.
Stencil crease_limit(const Cage& c, const NurccRules& rules, int v) {
  std::vector<int> creases;
  for (int e : rules.star_of(v).edges)
    if (sharp(c.edges[e])) creases.push_back(e);
  const int a = other_end(c.edges[creases[0]], v), b = other_end(c.edges[creases[1]], v);
  const auto m = limit_mask(rules.continuation(creases[0], a), c.edges[creases[0]].interval,
                            c.edges[creases[1]].interval, rules.continuation(creases[1], b));
  return {{a, m[0]}, {v, m[1]}, {b, m[2]}};
}

// The faces of `c` touching `ring`, as a cage of their own with the same
// intervals and sharpness; `local` receives each vertex's index in it.
Cage faces_around(const Cage& c, const NurccRules& rules, const std::vector<int>& ring, std::vector<int>& faces,
                  std::map<int, int>& local) {
  for (int x : ring) faces.insert(faces.end(), rules.star_of(x).faces.begin(), rules.star_of(x).faces.end());
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  Cage sub;
  for (int f : faces) {
    std::array<int, 4> q{};
    for (int k = 0; k < 4; ++k) q[k] = local.emplace(c.faces[f][k], static_cast<int>(local.size())).first->second;
    sub.faces.push_back(q);
  }
  sub.points = Eigen::MatrixXd::Zero(static_cast<int>(local.size()), 3);
  build_cage_edges(sub);
  std::map<std::pair<int, int>, int> parent_edge;
  for (int f : faces)
    for (int k = 0; k < 4; ++k) parent_edge[std::minmax(c.faces[f][k], c.faces[f][(k + 1) % 4])] = c.face_edges[f][k];
  std::vector<int> global(local.size());
  for (const auto& [g, l] : local) global[l] = g;
  for (auto& e : sub.edges) {
    const CageEdge& from = c.edges[parent_edge.at(std::minmax(global[e.vertices[0]], global[e.vertices[1]]))];
    e.interval = from.interval;
    e.sharpness = from.sharpness;
  }
  return sub;
}

// A smooth extraordinary vertex v1 of a cage refined at least once, where
// the refinement of its ring (v1, its spokes' ends, its faces' far corners)
// is stationary (every interval near it half of a parent spoke's or face's):
// the limit is the ring weighted by the left eigenvector of that ring's
// refinement matrix S for the eigenvalue 1, S read off the refinement
// weights of the faces around the ring.
Stencil extraordinary_limit(const Cage& c1, const NurccRules& rules, int v1) {
  const Spokes& s = rules.spokes_of(v1);
  const int n = static_cast<int>(s.edges.size()), m = 2 * n + 1;
  std::vector<int> ring{v1};
  for (int i = 0; i < n; ++i) ring.push_back(other_end(c1.edges[s.edges[i]], v1));
  for (int i = 0; i < n; ++i) {
    const auto& f = c1.faces[s.faces[i]];
    int k = 0;
    while (f[k] != v1) ++k;
    ring.push_back(f[(k + 2) % 4]);
  }
  std::vector<int> faces;
  std::map<int, int> local;
  Cage sub = faces_around(c1, rules, ring, faces, local);
  // The ring's children: v1's vertex point, its spokes' edge points, its faces' face points.
  const int nf = static_cast<int>(sub.faces.size()), ne = static_cast<int>(sub.edges.size());
  std::vector<int> child{nf + ne + local.at(v1)};
  for (int i = 0; i < n; ++i) {
    const auto key = std::minmax(local.at(v1), local.at(ring[1 + i]));
    for (int e = 0; e < ne; ++e)
      if (std::minmax(sub.edges[e].vertices[0], sub.edges[e].vertices[1]) == key) child.push_back(nf + e);
  }
  for (int i = 0; i < n; ++i)
    child.push_back(static_cast<int>(std::lower_bound(faces.begin(), faces.end(), s.faces[i]) - faces.begin()));
  const StencilMatrix W = refinement(sub).weights;
  Eigen::MatrixXd S(m, m);
  for (int row = 0; row < m; ++row)
    for (int col = 0; col < m; ++col) S(row, col) = W.coeff(child[row], local.at(ring[col]));
  Eigen::MatrixXd A(m + 1, m);
  A.topRows(m) = S.transpose() - Eigen::MatrixXd::Identity(m, m);
  A.row(m).setOnes();
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m + 1);
  rhs[m] = 1.0;
  const Eigen::VectorXd l = A.colPivHouseholderQr().solve(rhs);
  Stencil out;
  for (int c = 0; c < m; ++c) out.emplace_back(ring[c], l[c]);
  return out;}

}  // namespace

CageRefinement refinement(const Cage& cage) {
  require_nurcc(cage);
  const NurccRules rules(cage);
  const int nf = static_cast<int>(cage.faces.size()), ne = static_cast<int>(cage.edges.size());
  const int nv = static_cast<int>(cage.points.rows());
  std::vector<Stencil> rows(static_cast<size_t>(nf + ne + nv));
  for (int f = 0; f < nf; ++f) rows[f] = rules.face_point(f);
  const std::vector<Stencil> face_points(rows.begin(), rows.begin() + nf);
  for (int e = 0; e < ne; ++e) rows[nf + e] = rules.edge_point(e, face_points);
  const std::vector<Stencil> edge_points(rows.begin() + nf, rows.begin() + nf + ne);
  for (int v = 0; v < nv; ++v) rows[nf + ne + v] = rules.vertex_point(v, edge_points, face_points);
  CageRefinement r;
  r.weights = stencil_rows(rows, nv);
  Cage& child = r.child;
  child.points = r.weights * cage.points;
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 4; ++k)
      child.faces.push_back({{nf + ne + cage.faces[f][k], nf + cage.face_edges[f][k], f,
                              nf + cage.face_edges[f][(k + 3) % 4]}});
  build_cage_edges(child);
  // Halves of a parent edge keep its sharpness and take half its interval;
  // an edge from an edge point to a face point takes half the face's
  // interval across that edge.
  for (auto& e : child.edges) {
    const int a = e.vertices[0], b = e.vertices[1];
    const int edge_point = (a >= nf && a < nf + ne) ? a : b;
    const int other = edge_point == a ? b : a;
    const int parent = edge_point - nf;
    if (other >= nf + ne) {
      e.sharpness = cage.edges[parent].sharpness;
      e.interval = cage.edges[parent].interval / 2.0;
    } else {
      e.interval = rules.width(other, parent) / 2.0;
    }
  }
  return r;
}

Cage refine_cage(const Cage& cage) { return refinement(cage).child; }

StencilMatrix limit_position_weights(const Cage& cage) {
  // From the cage refined once: there every vertex's ring refines alike at
  // every later step (the intervals beyond its spokes' ends are halves of
  // its own spokes'), which the masks and the eigenvector assume; in the
  // cage itself an extraordinary neighbour breaks that for its neighbours.
  const CageRefinement once = refinement(cage);
  const Cage& c1 = once.child;
  const NurccRules rules(c1);
  const int offset = static_cast<int>(cage.faces.size() + cage.edges.size());
  std::vector<Stencil> rows(static_cast<size_t>(cage.points.rows()));
  for (int v = 0; v < cage.points.rows(); ++v) {
    const int v1 = offset + v;
    const CreaseStar c = crease_star(c1, rules.star_of(v1), v1);
    if (c.corner)
      rows[v] = {{v1, 1.0}};
    else if (c.ends.size() == 2)
      rows[v] = crease_limit(c1, rules, v1);
    else if (!rules.spokes_of(v1).closed)
      throw internal_error("T-NURCC limit positions: a smooth vertex on the border");
    else if (rules.spokes_of(v1).edges.size() == 4)
      rows[v] = regular_limit(c1, rules, v1);
    else
      rows[v] = extraordinary_limit(c1, rules, v1);
  }
  return StencilMatrix(stencil_rows(rows, static_cast<int>(c1.points.rows())) * once.weights);
}

Eigen::MatrixXd limit_positions(const Cage& cage) { return limit_position_weights(cage) * cage.points; }

DyadicLimit dyadic_limit(const Cage& cage, int levels) {
  if (levels < 0 || levels > 8) throw bad_input("dyadic_limit: levels must lie in [0, 8]");
  // Each face of the current level: the cage face it lies in and its corners' (s, t) there.
  std::vector<int> origin(cage.faces.size());
  std::vector<std::array<Eigen::Vector2d, 4>> corner(cage.faces.size());
  for (size_t f = 0; f < cage.faces.size(); ++f) {
    origin[f] = static_cast<int>(f);
    corner[f] = {{Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0), Eigen::Vector2d(1, 1), Eigen::Vector2d(0, 1)}};
  }
  Cage c = cage;
  StencilMatrix W(cage.points.rows(), cage.points.rows());
  W.setIdentity();
  for (int level = 0; level < levels; ++level) {
    const CageRefinement r = refinement(c);
    W = StencilMatrix(r.weights * W);
    std::vector<int> child_origin(4 * c.faces.size());
    std::vector<std::array<Eigen::Vector2d, 4>> child_corner(4 * c.faces.size());
    for (size_t f = 0; f < c.faces.size(); ++f) {
      const auto& q = corner[f];
      const Eigen::Vector2d centre = 0.25 * (q[0] + q[1] + q[2] + q[3]);
      for (int k = 0; k < 4; ++k) {  // child 4 f + k: (vertex k, edge k, face, edge k - 1)
        child_origin[4 * f + k] = origin[f];
        child_corner[4 * f + k] = {{q[k], 0.5 * (q[k] + q[(k + 1) % 4]), centre, 0.5 * (q[(k + 3) % 4] + q[k])}};
      }
    }
    origin = std::move(child_origin);
    corner = std::move(child_corner);
    c = r.child;
  }
  const StencilMatrix at_vertices = StencilMatrix(limit_position_weights(c) * W);
  const int n = 1 << levels, side = n + 1;
  DyadicLimit out;
  out.levels = levels;
  std::vector<int> vertex(cage.faces.size() * static_cast<size_t>(side * side), -1);
  for (size_t f = 0; f < c.faces.size(); ++f)
    for (int k = 0; k < 4; ++k) {
      const int i = static_cast<int>(std::lround(corner[f][k][0] * n)), j = static_cast<int>(std::lround(corner[f][k][1] * n));
      vertex[static_cast<size_t>(origin[f]) * side * side + i + side * j] = c.faces[f][k];
    }
  std::vector<Eigen::Triplet<double>> t;
  for (size_t g = 0; g < vertex.size(); ++g) {
    const int f = static_cast<int>(g / (side * side)), ij = static_cast<int>(g % (side * side));
    out.at.push_back({f, double(ij % side) / n, double(ij / side) / n});
    for (StencilMatrix::InnerIterator it(at_vertices, vertex[g]); it; ++it)
      t.emplace_back(static_cast<int>(g), static_cast<int>(it.col()), it.value());
  }
  out.weights.resize(static_cast<int>(vertex.size()), cage.points.rows());
  out.weights.setFromTriplets(t.begin(), t.end());
  return out;
}

}  // namespace igaprep::spline
