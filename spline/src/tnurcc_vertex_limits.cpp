#include "igaprep/spline/tnurcc_refine.h"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <cmath>
#include <map>

#include "nurcc_rules.h"

namespace igaprep::spline {
namespace {

using namespace detail;

// The cubic B-spline's value at the knot between intervals a (before the
// point) and b (after it), pa beyond the point before and rb beyond the
// point after: the weights of (point before, the point, point after), by
// blossoms (f(u, u, u) from the two points' neighbours).
std::array<double, 3> limit_mask(double pa, double a, double b, double rb) {
  const double before = (b / (a + b)) * (b / (pa + a + b)), after = (a / (a + b)) * (a / (a + b + rb));
  return {{before, 1.0 - before - after, after}};
}

// The derivative of that cubic at the knot, per unit of the knot parameter:
// 3 (Q2 - Q1) / (a + b), Q1 = f(u-, u, u) and Q2 = f(u, u, u+).
std::array<double, 3> derivative_mask(double pa, double a, double b, double rb) {
  const double k = 3.0 / (a + b), before = -k * b / (pa + a + b), after = k * a / (a + b + rb);
  return {{before, -(before + after), after}};
}

using Mask = std::array<double, 3> (*)(double, double, double, double);

// A valence-4 smooth vertex: the tensor product of a mask along its spokes
// 2 -> 0 and one along 3 -> 1; face i's far corner takes the product of
// spoke i's and spoke i + 1's end weights.
Stencil regular_stencil(const Cage& c, const NurccRules& rules, int v, Mask along_s, Mask along_t) {
  const Spokes& s = rules.spokes_of(v);
  std::array<int, 4> end{};
  std::array<double, 4> h{}, beyond{};
  for (int i = 0; i < 4; ++i) {
    end[i] = other_end(c.edges[s.edges[i]], v);
    h[i] = c.edges[s.edges[i]].interval;
    beyond[i] = rules.continuation(s.edges[i], end[i]);
  }
  const auto ms = along_s(beyond[2], h[2], h[0], beyond[0]), mt = along_t(beyond[3], h[3], h[1], beyond[1]);
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

Stencil regular_limit(const Cage& c, const NurccRules& rules, int v) {
  return regular_stencil(c, rules, v, limit_mask, limit_mask);
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
// the ring and its refinement matrix S, read off the refinement weights of
// the faces around the ring.
struct Ring {
  std::vector<int> points;  // v1, spoke ends 0..n-1, far corners 0..n-1
  Eigen::MatrixXd S;
};

Ring extraordinary_ring(const Cage& c1, const NurccRules& rules, int v1) {
  const Spokes& s = rules.spokes_of(v1);
  const int n = static_cast<int>(s.edges.size()), m = 2 * n + 1;
  Ring ring;
  ring.points.push_back(v1);
  for (int i = 0; i < n; ++i) ring.points.push_back(other_end(c1.edges[s.edges[i]], v1));
  for (int i = 0; i < n; ++i) {
    const auto& f = c1.faces[s.faces[i]];
    int k = 0;
    while (f[k] != v1) ++k;
    ring.points.push_back(f[(k + 2) % 4]);
  }
  std::vector<int> faces;
  std::map<int, int> local;
  const Cage sub = faces_around(c1, rules, ring.points, faces, local);
  // The ring's children: v1's vertex point, its spokes' edge points, its faces' face points.
  const int nf = static_cast<int>(sub.faces.size()), ne = static_cast<int>(sub.edges.size());
  std::vector<int> child{nf + ne + local.at(v1)};
  for (int i = 0; i < n; ++i) {
    const auto key = std::minmax(local.at(v1), local.at(ring.points[1 + i]));
    for (int e = 0; e < ne; ++e)
      if (std::minmax(sub.edges[e].vertices[0], sub.edges[e].vertices[1]) == key) child.push_back(nf + e);
  }
  for (int i = 0; i < n; ++i)
    child.push_back(static_cast<int>(std::lower_bound(faces.begin(), faces.end(), s.faces[i]) - faces.begin()));
  const StencilMatrix W = refinement(sub).weights;
  ring.S.resize(m, m);
  for (int row = 0; row < m; ++row)
    for (int col = 0; col < m; ++col) ring.S(row, col) = W.coeff(child[row], local.at(ring.points[col]));
  return ring;
}

Stencil ring_stencil(const Ring& ring, const Eigen::VectorXd& weights) {
  Stencil out;
  for (int c = 0; c < weights.size(); ++c) out.emplace_back(ring.points[c], weights[c]);
  return out;
}

// The limit: the ring weighted by S's left eigenvector for the eigenvalue 1.
Stencil extraordinary_limit(const Cage& c1, const NurccRules& rules, int v1) {
  const Ring ring = extraordinary_ring(c1, rules, v1);
  const int m = static_cast<int>(ring.S.rows());
  Eigen::MatrixXd A(m + 1, m);
  A.topRows(m) = ring.S.transpose() - Eigen::MatrixXd::Identity(m, m);
  A.row(m).setOnes();
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m + 1);
  rhs[m] = 1.0;
  return ring_stencil(ring, A.colPivHouseholderQr().solve(rhs));
}

// Two tangents: S's left eigenvectors for its subdominant eigenvalues (a
// complex pair's real and imaginary parts), ordered so that the spokes'
// ends wind round v1 in the tangent plane as the faces do (then the first
// cross the second points out of the surface).
std::array<Stencil, 2> extraordinary_tangents(const Cage& c1, const NurccRules& rules, int v1) {
  const Ring ring = extraordinary_ring(c1, rules, v1);
  const int m = static_cast<int>(ring.S.rows()), n = (m - 1) / 2;
  const Eigen::EigenSolver<Eigen::MatrixXd> es(ring.S.transpose());
  std::vector<int> order(m);
  for (int i = 0; i < m; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return std::abs(es.eigenvalues()[a]) > std::abs(es.eigenvalues()[b]); });
  const Eigen::VectorXcd l2 = es.eigenvectors().col(order[1]);
  Eigen::VectorXd t1 = l2.real(), t2 = es.eigenvalues()[order[1]].imag() != 0.0 ? Eigen::VectorXd(l2.imag())
                                                                                 : Eigen::VectorXd(es.eigenvectors().col(order[2]).real());
  double winding = 0.0;
  for (int i = 0; i < n; ++i) {
    const int a = 1 + i, b = 1 + (i + 1) % n;
    winding += t1[a] * t2[b] - t2[a] * t1[b];
  }
  if (winding < 0.0) t2 = -t2;
  return {{ring_stencil(ring, t1), ring_stencil(ring, t2)}};
}

}  // namespace

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

VertexTangentWeights limit_tangent_weights(const Cage& cage) {
  const CageRefinement once = refinement(cage);
  const Cage& c1 = once.child;
  const NurccRules rules(c1);
  const int offset = static_cast<int>(cage.faces.size() + cage.edges.size());
  std::vector<Stencil> first(static_cast<size_t>(cage.points.rows())), second(first.size());
  for (int v = 0; v < cage.points.rows(); ++v) {
    const int v1 = offset + v;
    const CreaseStar c = crease_star(c1, rules.star_of(v1), v1);
    if (c.corner || !c.ends.empty() || !rules.spokes_of(v1).closed) continue;  // one-sided there: zero rows
    if (rules.spokes_of(v1).edges.size() == 4) {
      first[v] = regular_stencil(c1, rules, v1, derivative_mask, limit_mask);
      second[v] = regular_stencil(c1, rules, v1, limit_mask, derivative_mask);
    } else {
      const auto t = extraordinary_tangents(c1, rules, v1);
      first[v] = t[0];
      second[v] = t[1];
    }
  }
  const int columns = static_cast<int>(c1.points.rows());
  VertexTangentWeights out;
  out.first = StencilMatrix(stencil_rows(first, columns) * once.weights);
  out.second = StencilMatrix(stencil_rows(second, columns) * once.weights);
  return out;
}

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
