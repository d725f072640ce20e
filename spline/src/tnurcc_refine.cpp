#include "igaprep/spline/tnurcc_refine.h"

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

Eigen::RowVector3d vertex_point(const Cage& cage, const VertexStar& star, int v, const Eigen::MatrixXd& face_points) {
  const Eigen::RowVector3d p = cage.points.row(v);
  const CreaseStar c = crease_star(cage, star, v);
  const int n = static_cast<int>(star.edges.size());
  if (c.corner) return p;
  if (c.ends.size() == 2) return (cage.points.row(c.ends[0]) + 6.0 * p + cage.points.row(c.ends[1])) / 8.0;
  Eigen::RowVector3d q = Eigen::RowVector3d::Zero(), r = Eigen::RowVector3d::Zero();
  for (int f : star.faces) q += face_points.row(f);
  for (int e : star.edges) r += 0.5 * (p + cage.points.row(other_end(cage.edges[e], v)));
  q /= double(star.faces.size());
  r /= double(n);
  return (q + 2.0 * r + (n - 3.0) * p) / double(n);
}

// Equal intervals, every edge smooth or infinitely sharp: what the rules here cover.
void require_uniform_rules(const Cage& cage) {
  if (!uniform_intervals(cage, 1e-12))
    throw bad_input("T-NURCC refinement: the cage's knot intervals differ; the non-uniform rules are not written yet");
  for (const auto& e : cage.edges)
    if (e.sharpness > 0.0 && e.sharpness < kInfiniteSharpness)
      throw bad_input("T-NURCC refinement: edge (" + std::to_string(e.vertices[0]) + ", " +
                      std::to_string(e.vertices[1]) + ") is semi-sharp; only smooth and infinitely sharp edges are");
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
  require_uniform_rules(cage);
  const int nf = static_cast<int>(cage.faces.size()), ne = static_cast<int>(cage.edges.size());
  const int nv = static_cast<int>(cage.points.rows());
  Cage child;
  child.points.resize(nf + ne + nv, 3);
  for (int f = 0; f < nf; ++f) {
    Eigen::RowVector3d c = Eigen::RowVector3d::Zero();
    for (int v : cage.faces[f]) c += cage.points.row(v);
    child.points.row(f) = c / 4.0;
  }
  const Eigen::MatrixXd face_points = child.points.topRows(nf);
  for (int e = 0; e < ne; ++e) {
    const CageEdge& edge = cage.edges[e];
    Eigen::RowVector3d x = cage.points.row(edge.vertices[0]) + cage.points.row(edge.vertices[1]);
    child.points.row(nf + e) =
        sharp(edge) ? Eigen::RowVector3d(x / 2.0)
                    : Eigen::RowVector3d((x + face_points.row(edge.faces[0]) + face_points.row(edge.faces[1])) / 4.0);
  }
  const std::vector<VertexStar> star = stars(cage);
  for (int v = 0; v < nv; ++v) child.points.row(nf + ne + v) = vertex_point(cage, star[v], v, face_points);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 4; ++k)
      child.faces.push_back({{nf + ne + cage.faces[f][k], nf + cage.face_edges[f][k], f,
                              nf + cage.face_edges[f][(k + 3) % 4]}});
  build_cage_edges(child);
  // Halves of a parent edge keep its sharpness; every interval halves.
  const double interval = cage.edges.empty() ? 1.0 : cage.edges[0].interval / 2.0;
  for (auto& e : child.edges) {
    e.interval = interval;
    const int a = e.vertices[0], b = e.vertices[1];
    const int edge_point = (a >= nf && a < nf + ne) ? a : ((b >= nf && b < nf + ne) ? b : -1);
    const int other = edge_point == a ? b : a;
    if (edge_point >= 0 && other >= nf + ne) e.sharpness = cage.edges[edge_point - nf].sharpness;
  }
  return child;
}

}  // namespace igaprep::spline
