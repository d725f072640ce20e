#include "igaprep/spline/tnurcc_refine.h"

#include <algorithm>

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

 private:
  const Cage& c_;
  std::vector<VertexStar> star_;
  std::vector<Spokes> spokes_;
};

// Every edge smooth or infinitely sharp: what the rules here cover.
void require_smooth_or_infinitely_sharp(const Cage& cage) {
  for (const auto& e : cage.edges)
    if (e.sharpness > 0.0 && e.sharpness < kInfiniteSharpness)
      throw bad_input("T-NURCC refinement: edge (" + std::to_string(e.vertices[0]) + ", " +
                      std::to_string(e.vertices[1]) + ") is semi-sharp; only smooth and infinitely sharp edges are");
}

// Catmull-Clark's masks need equal intervals.
void require_uniform_rules(const Cage& cage) {
  if (!uniform_intervals(cage, 1e-12))
    throw bad_input("T-NURCC limit positions: the cage's knot intervals differ; the masks are Catmull-Clark's");
  require_smooth_or_infinitely_sharp(cage);
}

}  // namespace

Eigen::MatrixXd limit_positions(const Cage& cage) {
  require_uniform_rules(cage);
  const std::vector<VertexStar> star = stars(cage);
  Eigen::MatrixXd out(cage.points.rows(), 3);
  for (int v = 0; v < cage.points.rows(); ++v) {
    const Eigen::RowVector3d p = cage.points.row(v);
    const CreaseStar c = crease_star(cage, star[v], v);
    if (c.corner) {
      out.row(v) = p;
    } else if (c.ends.size() == 2) {
      out.row(v) = (cage.points.row(c.ends[0]) + 4.0 * p + cage.points.row(c.ends[1])) / 6.0;
    } else {
      const double n = double(star[v].edges.size());
      Eigen::RowVector3d sum = n * n * p;
      for (int e : star[v].edges) sum += 4.0 * cage.points.row(other_end(cage.edges[e], v));
      for (int f : star[v].faces)
        for (int k = 0; k < 4; ++k)
          if (cage.faces[f][k] == v) sum += cage.points.row(cage.faces[f][(k + 2) % 4]);
      out.row(v) = sum / (n * (n + 5.0));
    }
  }
  return out;
}

Cage refine_cage(const Cage& cage) {
  require_smooth_or_infinitely_sharp(cage);
  if (!opposite_edge_violations(cage).empty())
    throw bad_input("T-NURCC refinement: opposite edges of a face carry different knot intervals");
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

}  // namespace igaprep::spline
