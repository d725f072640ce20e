#include "igaprep/spline/tnurcc_refine.h"

#include "nurcc_rules.h"

namespace igaprep::spline {

using namespace detail;

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

}  // namespace igaprep::spline
