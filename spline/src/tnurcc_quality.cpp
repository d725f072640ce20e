#include "igaprep/spline/tnurcc_quality.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "igaprep/core/angle.h"
#include "igaprep/spline/evaluate.h"
#include "igaprep/spline/knot_vector.h"


namespace igaprep::spline {
namespace {

bool joins_two_sides(const Cage& cage, const CageEdge& e) {
  if (e.faces[1] < 0 || cage.origin.empty()) return false;
  const CageFaceOrigin &a = cage.origin[e.faces[0]], &b = cage.origin[e.faces[1]];
  return a.patch != b.patch || a.side != b.side;
}

void add(NormalJumps& j, double angle, double gap, const Eigen::Vector3d& where) {
  if (angle > j.max || j.points == 0) {
    j.max = angle;
    j.max_location = where;
  }
  j.mean += angle;
  j.max_gap = std::max(j.max_gap, gap);
  ++j.points;
}

void finish(NormalJumps& j) {
  if (j.points > 0) j.mean /= double(j.points);
}

// Corner index of vertex v in face f.
int corner_of(const Cage& cage, int f, int v) {
  for (int k = 0; k < 4; ++k)
    if (cage.faces[f][k] == v) return k;
  return -1;
}

// A point of the side surface of face f at fraction a from vertex `from` to
// vertex `to` (both corners of f), between their Greville abscissae, with
// the surface's normal turned out of the patch (against the patch's
// derivative into its interior, so a folded cage face cannot turn it).
struct SidePoint {
  Eigen::Vector3d x, normal;
};
SidePoint side_point(const MultiPatch& mp, const Cage& cage, int f, int from, int to, double a) {
  const CageFaceOrigin& o = cage.origin[f];
  const Patch& p = mp.patches[o.patch];
  const auto td = o.side.tangent_directions();
  const int d = o.side.direction();
  const auto& n0 = o.net[corner_of(cage, f, from)];
  const auto& n1 = o.net[corner_of(cage, f, to)];
  Eigen::Vector3d uvw;
  for (int k = 0; k < 2; ++k) {
    const std::vector<double> g = greville_abscissae(p.knots[td[k]], p.degrees[td[k]]);
    uvw[td[k]] = (1.0 - a) * g[n0[k]] + a * g[n1[k]];
  }
  const auto& U = p.knots[d];
  uvw[d] = o.side.parameter() ? U[U.size() - p.degrees[d] - 1] : U[p.degrees[d]];
  const Eigen::Matrix3d J = evaluate_jacobian(p, uvw);
  Eigen::Vector3d n = J.col(td[0]).cross(J.col(td[1]));
  const Eigen::Vector3d out = o.side.parameter() ? Eigen::Vector3d(J.col(d)) : Eigen::Vector3d(-J.col(d));
  if (n.dot(out) < 0) n = -n;
  return {evaluate_point(p, uvw), n};
}

std::vector<double> fractions(int samples) {
  std::vector<double> a(samples);
  for (int i = 0; i < samples; ++i) a[i] = (i + 1.0) / (samples + 1.0);
  return a;
}

}  // namespace

NormalJumps model_normal_jumps(const MultiPatch& mp, const Cage& cage, int samples) {
  NormalJumps j;
  for (const auto& e : cage.edges) {
    if (e.sharpness > 0.0 || !joins_two_sides(cage, e)) continue;
    const int v0 = e.vertices[0], v1 = e.vertices[1];
    for (double a : fractions(samples)) {
      const SidePoint p = side_point(mp, cage, e.faces[0], v0, v1, a);
      const SidePoint q = side_point(mp, cage, e.faces[1], v0, v1, a);
      add(j, angle_degrees(p.normal, q.normal), (p.x - q.x).norm(), p.x);
    }
  }
  finish(j);
  return j;
}

NormalJumps limit_normal_jumps(const Cage& cage, JumpEdges edges, int samples, const LimitOptions& options) {
  // Two locations per sample: on the edge's first face, and the same place on its second.
  std::vector<LimitLocation> at;
  for (const auto& e : cage.edges) {
    if (e.faces[1] < 0 || (e.sharpness > 0.0) != (edges == JumpEdges::creases)) continue;
    if (edges == JumpEdges::smooth_patch_edges && !joins_two_sides(cage, e)) continue;
    const int f = e.faces[0], g = e.faces[1];
    const int kf = corner_of(cage, f, e.vertices[0]), kg = corner_of(cage, g, e.vertices[1]);
    // Each face runs the edge from one of its corners: f from vertices[0] or to it.
    const bool f_forward = cage.faces[f][(kf + 1) % 4] == e.vertices[1];
    const bool g_forward = cage.faces[g][(kg + 1) % 4] == e.vertices[0];
    const int edge_f = f_forward ? kf : (kf + 3) % 4, edge_g = g_forward ? kg : (kg + 3) % 4;
    for (double a : fractions(samples)) {
      at.push_back(edge_location(f, edge_f, f_forward ? a : 1.0 - a));
      at.push_back(edge_location(g, edge_g, g_forward ? 1.0 - a : a));
    }
  }
  NormalJumps j;
  if (at.empty()) return j;
  const LimitValues v = limit_values(limit_stencils(cage, at, options), cage.points);
  for (int i = 0; i + 1 < v.point.rows(); i += 2)
    add(j, angle_degrees(v.normal.row(i).transpose(), v.normal.row(i + 1).transpose()),
        (v.point.row(i) - v.point.row(i + 1)).norm(), v.point.row(i).transpose());
  finish(j);
  return j;
}

}  // namespace igaprep::spline
