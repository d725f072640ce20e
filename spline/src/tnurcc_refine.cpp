#include "igaprep/spline/tnurcc_refine.h"

#include <Eigen/QR>
#include <algorithm>
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
  static Eigen::RowVector3d edge_rule(const Eigen::RowVector3d& a, const Eigen::RowVector3d& b, double p, double q,
                                      double r) {
    return ((q + 2.0 * r) * a + (2.0 * p + q) * b) / (2.0 * (p + q + r));
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
  Eigen::RowVector3d face_point(int f) const {
    const auto& v = c_.faces[f];
    const double qs = c_.edges[c_.face_edges[f][0]].interval, qt = c_.edges[c_.face_edges[f][3]].interval;
    const double ps = across(f, 3), rs = across(f, 1), pt = across(f, 0), rt = across(f, 2);
    const double s0 = (0.5 * qs + rs) / (ps + qs + rs), s1 = 1.0 - s0;
    const double t0 = (0.5 * qt + rt) / (pt + qt + rt), t1 = 1.0 - t0;
    return t0 * (s0 * c_.points.row(v[0]) + s1 * c_.points.row(v[1])) +
           t1 * (s0 * c_.points.row(v[3]) + s1 * c_.points.row(v[2]));
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
  Eigen::RowVector3d row_point(int e) const {
    const CageEdge& edge = c_.edges[e];
    const int a = edge.vertices[0], b = edge.vertices[1];
    return edge_rule(c_.points.row(a), c_.points.row(b), continuation(e, a), edge.interval, continuation(e, b));
  }

  // The interval of face f across edge e (its edges at e's ends).
  double width(int f, int e) const {
    int k = 0;
    while (c_.face_edges[f][k] != e) ++k;
    return c_.edges[c_.face_edges[f][(k + 1) % 4]].interval;
  }

  Eigen::RowVector3d edge_point(int e, const Eigen::MatrixXd& face_points) const {
    const CageEdge& edge = c_.edges[e];
    const Eigen::RowVector3d m = row_point(e);
    if (sharp(edge)) return m;
    const int f1 = edge.faces[0], f2 = edge.faces[1];
    const double w1 = width(f1, e), w2 = width(f2, e);
    return 0.5 * m + 0.5 * (w2 * face_points.row(f1) + w1 * face_points.row(f2)) / (w1 + w2);
  }

  Eigen::RowVector3d vertex_point(int v, const Eigen::MatrixXd& edge_points, const Eigen::MatrixXd& face_points) const {
    const Eigen::RowVector3d p = c_.points.row(v);
    const CreaseStar cs = crease_star(c_, star_[v], v);
    if (cs.corner) return p;
    if (cs.ends.size() == 2) {
      std::vector<int> creases;
      for (int x : star_[v].edges)
        if (sharp(c_.edges[x])) creases.push_back(x);
      const double da = c_.edges[creases[0]].interval, db = c_.edges[creases[1]].interval;
      return 0.5 * p + (db * edge_points.row(creases[0]) + da * edge_points.row(creases[1])) / (2.0 * (da + db));
    }
    const Spokes& s = spokes_[v];
    const int n = static_cast<int>(s.edges.size());
    if (!s.closed) throw internal_error("T-NURCC refinement: a smooth vertex on the border");
    auto h = [&](int i) { return c_.edges[s.edges[((i % n) + n) % n]].interval; };
    Eigen::RowVector3d m_sum = Eigen::RowVector3d::Zero(), f_sum = Eigen::RowVector3d::Zero();
    double m_weight = 0.0, f_weight = 0.0;
    for (int i = 0; i < n; ++i) {
      const double m = 0.5 * (h(i - 1) + h(i + 1)) * (h(i - 2) + h(i + 2)), f = h(i - 1) * h(i + 2);
      m_sum += m * row_point(s.edges[i]);
      m_weight += m;
      f_sum += f * face_points.row(s.faces[i]);
      f_weight += f;
    }
    return ((n - 3.0) * p + 2.0 * m_sum / m_weight + f_sum / f_weight) / double(n);
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
Eigen::RowVector3d regular_limit(const Cage& c, const NurccRules& rules, int v) {
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
  Eigen::RowVector3d x = ms[1] * mt[1] * c.points.row(v);
  for (int i = 0; i < 4; ++i) {
    const double across = i % 2 == 0 ? mt[1] : ms[1];
    x += w[i] * across * c.points.row(end[i]);
    const auto& f = c.faces[s.faces[i]];
    int k = 0;
    while (f[k] != v) ++k;
    x += w[i] * w[(i + 1) % 4] * c.points.row(f[(k + 2) % 4]);
  }
  return x;
}

// A crease vertex: the mask along its two crease edges.
Eigen::RowVector3d crease_limit(const Cage& c, const NurccRules& rules, int v) {
  std::vector<int> creases;
  for (int e : rules.star_of(v).edges)
    if (sharp(c.edges[e])) creases.push_back(e);
  const int a = other_end(c.edges[creases[0]], v), b = other_end(c.edges[creases[1]], v);
  const auto m = limit_mask(rules.continuation(creases[0], a), c.edges[creases[0]].interval,
                            c.edges[creases[1]].interval, rules.continuation(creases[1], b));
  return m[0] * c.points.row(a) + m[1] * c.points.row(v) + m[2] * c.points.row(b);
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
// refinement matrix S for the eigenvalue 1. S's columns come from refining
// the faces around the ring with one ring point at 1 and the others at 0.
Eigen::RowVector3d extraordinary_limit(const Cage& c1, const NurccRules& rules, int v1) {
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
  Eigen::MatrixXd S(m, m);
  for (int c0 = 0; c0 < m; c0 += 3) {
    sub.points.setZero();
    for (int k = 0; k < 3 && c0 + k < m; ++k) sub.points(local.at(ring[c0 + k]), k) = 1.0;
    const Cage r = refine_cage(sub);
    for (int k = 0; k < 3 && c0 + k < m; ++k)
      for (int row = 0; row < m; ++row) S(row, c0 + k) = r.points(child[row], k);
  }
  Eigen::MatrixXd A(m + 1, m);
  A.topRows(m) = S.transpose() - Eigen::MatrixXd::Identity(m, m);
  A.row(m).setOnes();
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m + 1);
  rhs[m] = 1.0;
  const Eigen::VectorXd l = A.colPivHouseholderQr().solve(rhs);
  Eigen::RowVector3d x = Eigen::RowVector3d::Zero();
  for (int c = 0; c < m; ++c) x += l[c] * c1.points.row(ring[c]);
  return x;
}

}  // namespace

Cage refine_cage(const Cage& cage) {
  require_nurcc(cage);
  const NurccRules rules(cage);
  const int nf = static_cast<int>(cage.faces.size()), ne = static_cast<int>(cage.edges.size());
  const int nv = static_cast<int>(cage.points.rows());
  Cage child;
  child.points.resize(nf + ne + nv, 3);
  for (int f = 0; f < nf; ++f) child.points.row(f) = rules.face_point(f);
  const Eigen::MatrixXd face_points = child.points.topRows(nf);
  for (int e = 0; e < ne; ++e) child.points.row(nf + e) = rules.edge_point(e, face_points);
  const Eigen::MatrixXd edge_points = child.points.middleRows(nf, ne);
  for (int v = 0; v < nv; ++v) child.points.row(nf + ne + v) = rules.vertex_point(v, edge_points, face_points);
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
  return child;
}

Eigen::MatrixXd limit_positions(const Cage& cage) {
  // From the cage refined once: there every vertex's ring refines alike at
  // every later step (the intervals beyond its spokes' ends are halves of
  // its own spokes'), which the masks and the eigenvector assume; in the
  // cage itself an extraordinary neighbour breaks that for its neighbours.
  const Cage c1 = refine_cage(cage);
  const NurccRules rules(c1);
  const int offset = static_cast<int>(cage.faces.size() + cage.edges.size());
  Eigen::MatrixXd out(cage.points.rows(), 3);
  for (int v = 0; v < cage.points.rows(); ++v) {
    const int v1 = offset + v;
    const CreaseStar c = crease_star(c1, rules.star_of(v1), v1);
    if (c.corner) {
      out.row(v) = cage.points.row(v);
    } else if (c.ends.size() == 2) {
      out.row(v) = crease_limit(c1, rules, v1);
    } else if (!rules.spokes_of(v1).closed) {
      throw internal_error("T-NURCC limit positions: a smooth vertex on the border");
    } else if (rules.spokes_of(v1).edges.size() == 4) {
      out.row(v) = regular_limit(c1, rules, v1);
    } else {
      out.row(v) = extraordinary_limit(c1, rules, v1);
    }
  }
  return out;
}

}  // namespace igaprep::spline
