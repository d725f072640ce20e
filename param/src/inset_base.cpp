#include "igaprep/param/inset_base.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <utility>

#include <Eigen/Geometry>

#include "igaprep/core/error.h"
#include "igaprep/mesh/self_intersections.h"
#include "igaprep/param/base_layout.h"
#include "igaprep/param/sheet_topology.h"

namespace igaprep::param {

int split_sheet_along_line(mesh::TriMesh& sheet, Eigen::MatrixXd& uv, int axis, double c, double snap,
                           const std::vector<char>& unsnapped) {
  for (Eigen::Index v = 0; v < uv.rows(); ++v)
    if (std::abs(uv(v, axis) - c) < snap && !(v < static_cast<Eigen::Index>(unsnapped.size()) && unsnapped[v])) uv(v, axis) = c;

  std::vector<Eigen::Vector3d> P;
  std::vector<Eigen::Vector2d> Q;
  for (Eigen::Index v = 0; v < uv.rows(); ++v) P.push_back(sheet.V.row(v)), Q.push_back(uv.row(v));
  std::map<std::pair<int, int>, int> cut;  // edge -> new vertex
  auto side = [&](int v) { return Q[static_cast<std::size_t>(v)](axis) - c; };
  auto crossing = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    const auto it = cut.find(key);
    if (it != cut.end()) return it->second;
    const double t = side(key.first) / (side(key.first) - side(key.second));
    P.push_back((1.0 - t) * P[key.first] + t * P[key.second]);
    Eigen::Vector2d q = (1.0 - t) * Q[key.first] + t * Q[key.second];
    q(axis) = c;
    Q.push_back(q);
    const int id = static_cast<int>(P.size()) - 1;
    cut.emplace(key, id);
    return id;
  };
  std::vector<Eigen::Vector3i> faces;
  auto emit = [&](const std::vector<int>& poly) {
    for (std::size_t k = 1; k + 1 < poly.size(); ++k) faces.emplace_back(poly[0], poly[k], poly[k + 1]);
  };
  for (Eigen::Index f = 0; f < sheet.F.rows(); ++f) {
    std::vector<int> pos, neg;
    for (int k = 0; k < 3; ++k) {
      const int a = sheet.F(f, k), b = sheet.F(f, (k + 1) % 3);
      const double sa = side(a), sb = side(b);
      if (sa >= 0.0) pos.push_back(a);
      if (sa <= 0.0) neg.push_back(a);
      if ((sa > 0.0 && sb < 0.0) || (sa < 0.0 && sb > 0.0)) {
        const int x = crossing(a, b);
        pos.push_back(x);
        neg.push_back(x);
      }
    }
    if (pos.size() == 3 && neg.size() < 3) emit(pos);
    else if (neg.size() == 3 && pos.size() < 3) emit(neg);
    else {
      if (pos.size() >= 3) emit(pos);
      if (neg.size() >= 3) emit(neg);
    }
  }
  sheet.V.resize(static_cast<Eigen::Index>(P.size()), 3);
  uv.resize(static_cast<Eigen::Index>(Q.size()), 2);
  for (std::size_t v = 0; v < P.size(); ++v) {
    sheet.V.row(static_cast<Eigen::Index>(v)) = P[v].transpose();
    uv.row(static_cast<Eigen::Index>(v)) = Q[v].transpose();
  }
  sheet.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f) sheet.F.row(static_cast<Eigen::Index>(f)) = faces[f].transpose();
  return static_cast<int>(cut.size());
}

double narrowest_band(const RectilinearDomain& D) {
  double band = std::min(D.width, D.height);
  for (const DomainArm& arm : D.arms) band = std::min(band, arm.to - arm.from);
  for (const auto& h : D.holes) {
    band = std::min({band, h(0), h(1), D.width - h(2), D.height - h(3)});
    for (const auto& g : D.holes) {
      if (&g == &h) continue;
      const double gu = std::max(g(0) - h(2), h(0) - g(2)), gv = std::max(g(1) - h(3), h(1) - g(3));
      if (std::max(gu, gv) > 0.0) band = std::min(band, std::max(gu, gv));
    }
  }
  return band;
}

void smooth_sheet(mesh::TriMesh& sheet, const std::vector<char>& fixed, int rounds) {
  const Eigen::Index nv = sheet.V.rows();
  // Moves are along the vertex normal only: a tangential move would shift
  // the surface under its (u, v) parameterization.
  std::set<std::pair<int, int>> edges;
  for (Eigen::Index f = 0; f < sheet.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) edges.insert(std::minmax(sheet.F(f, k), sheet.F(f, (k + 1) % 3)));
  std::vector<std::vector<int>> nb(static_cast<std::size_t>(nv));
  for (const auto& e : edges) nb[e.first].push_back(e.second), nb[e.second].push_back(e.first);
  auto step = [&](double factor) {
    Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(nv, 3);
    for (Eigen::Index f = 0; f < sheet.F.rows(); ++f) {
      const Eigen::Vector3d a = (sheet.V.row(sheet.F(f, 1)) - sheet.V.row(sheet.F(f, 0))).transpose();
      const Eigen::Vector3d b = (sheet.V.row(sheet.F(f, 2)) - sheet.V.row(sheet.F(f, 0))).transpose();
      const Eigen::Vector3d n = a.cross(b);
      for (int k = 0; k < 3; ++k) normal.row(sheet.F(f, k)) += n.transpose();
    }
    Eigen::MatrixXd next = sheet.V;
    for (Eigen::Index v = 0; v < nv; ++v) {
      if (fixed[static_cast<std::size_t>(v)] || nb[v].empty() || normal.row(v).norm() == 0.0) continue;
      Eigen::RowVector3d mean = Eigen::RowVector3d::Zero();
      for (int u : nb[v]) mean += sheet.V.row(u);
      mean /= static_cast<double>(nb[v].size());
      const Eigen::RowVector3d n = normal.row(v).normalized();
      next.row(v) += factor * (mean - sheet.V.row(v)).dot(n) * n;
    }
    sheet.V = next;
  };
  for (int r = 0; r < rounds; ++r) step(0.5), step(-0.53);  // Taubin: smooths without shrinking
}

int collapse_short_edges(mesh::TriMesh& sheet, Eigen::MatrixXd& uv, const std::vector<char>& pinned, double min_length) {
  int collapsed = 0;
  std::vector<char> dead(static_cast<std::size_t>(sheet.F.rows()), 0);
  std::vector<std::vector<int>> faces_of(static_cast<std::size_t>(sheet.V.rows()));
  for (Eigen::Index f = 0; f < sheet.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) faces_of[sheet.F(f, k)].push_back(static_cast<int>(f));
  auto signed_area = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
    return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
  };
  auto uv_of = [&](int v) -> Eigen::Vector2d { return uv.row(v).transpose(); };
  for (Eigen::Index f = 0; f < sheet.F.rows(); ++f) {
    if (dead[f]) continue;
    // A triangle turned over in (u, v) (two cut points a line put in the
    // wrong order, where the map is nearly degenerate) loses its shortest
    // (u, v) edge as if it had no length.
    int flipped_edge = -1;
    if (!(signed_area(uv_of(sheet.F(f, 0)), uv_of(sheet.F(f, 1)), uv_of(sheet.F(f, 2))) > 0.0)) {
      double shortest = std::numeric_limits<double>::infinity();
      for (int k = 0; k < 3; ++k)
        if (const double l = (uv.row(sheet.F(f, k)) - uv.row(sheet.F(f, (k + 1) % 3))).norm(); l < shortest)
          shortest = l, flipped_edge = k;
    }
    for (int k = 0; k < 3 && !dead[f]; ++k) {
      int keep = sheet.F(f, k), drop = sheet.F(f, (k + 1) % 3);
      // An edge of no length in (u, v) (two cut points that the line put at
      // one place, where the map is nearly degenerate) goes whatever its 3D
      // length and pins: its triangles have no area in (u, v).
      const bool same_uv =
          k == flipped_edge || (uv.row(keep) - uv.row(drop)).norm() <= 1e-12 * (1.0 + uv.row(keep).norm());
      if (!same_uv && (sheet.V.row(keep) - sheet.V.row(drop)).norm() >= min_length) continue;
      if (!same_uv && pinned[drop] && pinned[keep]) continue;
      if (pinned[drop]) std::swap(keep, drop);
      // Moving `drop` onto `keep` must not fold any surviving triangle in
      // (u, v); onto a vertex at the same (u, v) it changes none (whatever
      // triangles of no area there are about it).
      const bool same_place = (uv.row(keep) - uv.row(drop)).norm() == 0.0;
      bool ok = true;
      for (int g : faces_of[drop]) {
        if (same_place) break;
        if (dead[g]) continue;
        bool has_keep = false;
        Eigen::Vector2d p[3];
        for (int j = 0; j < 3; ++j) {
          const int v = sheet.F(g, j);
          has_keep |= v == keep;
          p[j] = uv.row(v == drop ? keep : v).transpose();
        }
        if (!has_keep && !(signed_area(p[0], p[1], p[2]) > 0.0)) ok = false;
      }
      if (!ok) continue;
      for (int g : faces_of[drop]) {
        if (dead[g]) continue;
        bool has_keep = false;
        for (int j = 0; j < 3; ++j) has_keep |= sheet.F(g, j) == keep;
        if (has_keep) {
          dead[g] = 1;
          continue;
        }
        for (int j = 0; j < 3; ++j)
          if (sheet.F(g, j) == drop) sheet.F(g, j) = keep;
        faces_of[keep].push_back(g);
      }
      ++collapsed;
    }
  }
  Eigen::MatrixXi F(sheet.F.rows(), 3);
  Eigen::Index n = 0;
  for (Eigen::Index f = 0; f < sheet.F.rows(); ++f)
    if (!dead[f]) F.row(n++) = sheet.F.row(f);
  sheet.F = F.topRows(n);
  return collapsed;
}

namespace {

bool same_line(double x, double c) { return std::abs(x - c) <= 1e-12 * (1.0 + std::abs(c)); }

// Per axis: whether p lies on one of the domain's lines in that axis (the
// outer sides and the holes' sides).
std::array<bool, 2> on_domain_lines(const RectilinearDomain& D, const Eigen::Vector2d& p) {
  std::vector<double> us{0.0, D.width}, vs{0.0, D.height};
  std::vector<Eigen::Vector4d> boxes = D.holes;
  for (const DomainArm& arm : D.arms) boxes.push_back(arm_box(D, arm));
  for (const auto& h : boxes) us.push_back(h(0)), us.push_back(h(2)), vs.push_back(h(1)), vs.push_back(h(3));
  std::array<bool, 2> on{{false, false}};
  for (double c : us) on[0] = on[0] || same_line(p.x(), c);
  for (double c : vs) on[1] = on[1] || same_line(p.y(), c);
  return on;
}

}  // namespace

bool sheet_self_intersects(const mesh::TriMesh& sheet, const std::string& name) {
  const auto pairs = mesh::find_self_intersections(sheet);
  if (!pairs)
    throw bad_input(name + ": cannot tell whether it intersects itself: it is not an oriented 2-manifold "
                           "(non-manifold, inconsistently oriented or a bad vertex index)");
  return !pairs->empty();
}

InsetBase inset_base_surface(const mesh::TriMesh& sheet, const Polycube2D& polycube, double inset, int smoothing) {
  if (!(inset > 0.0 && inset < 1.0))
    throw bad_input("inset base surface: inset = " + std::to_string(inset) + " is outside (0, 1)");
  const RectilinearDomain& D = polycube.domain;
  const double band = narrowest_band(D);
  const double d = 0.5 * inset * band;

  InsetBase out;
  out.inset = d;
  out.mesh = sheet;
  out.uv = polycube.uv;
  // Mean (u, v) edge length sets the snap distance.
  double mean_edge = 0.0;
  for (Eigen::Index f = 0; f < sheet.F.rows(); ++f)
    mean_edge += (polycube.uv.row(sheet.F(f, 0)) - polycube.uv.row(sheet.F(f, 1))).norm();
  mean_edge /= std::max<Eigen::Index>(1, sheet.F.rows());
  const double snap = 0.02 * mean_edge;
  // The cut lines: the outer sides moved in by d, the hole sides out by d,
  // each then shifted by up to 0.2 mean edges to where it passes farthest
  // from every vertex (a line through a vertex's neighbourhood leaves tiny
  // edges and slivers, which TetGen meshes into flat tets).
  std::map<std::pair<int, double>, double> placed;  // lines with one value are placed once (aligned hole sides stay aligned)
  auto place = [&](int axis, double c) {
    for (const auto& [key, value] : placed)
      if (key.first == axis && same_line(key.second, c)) return value;
    double best = c, best_gap = -1.0;
    for (int k = -8; k <= 8; ++k) {
      const double trial = c + 0.025 * k * mean_edge;
      double gap = std::numeric_limits<double>::infinity();
      for (Eigen::Index v = 0; v < out.uv.rows(); ++v) gap = std::min(gap, std::abs(out.uv(v, axis) - trial));
      if (gap > best_gap) best_gap = gap, best = trial;
    }
    // A vertex on a line placed before stays there: snapped onto a line
    // next to it (two holes' sides a band apart where the map squeezes) it
    // would leave triangles of no area between the two.
    std::vector<char> on_placed(static_cast<std::size_t>(out.uv.rows()), 0);
    for (const auto& [key, value] : placed)
      if (key.first == axis)
        for (Eigen::Index v = 0; v < out.uv.rows(); ++v) on_placed[static_cast<std::size_t>(v)] |= out.uv(v, axis) == value;
    split_sheet_along_line(out.mesh, out.uv, axis, best, snap, on_placed);
    placed[{axis, c}] = best;
    return best;
  };
  const double left = place(0, d), right = place(0, D.width - d), bottom = place(1, d), top = place(1, D.height - d);
  out.domain.width = right - left;
  out.domain.height = top - bottom;
  out.domain.hole_loop = D.hole_loop;
  for (const auto& h : D.holes) {
    const double hl = place(0, h(0) - d), hr = place(0, h(2) + d), hb = place(1, h(1) - d), ht = place(1, h(3) + d);
    out.domain.holes.emplace_back(hl - left, hb - bottom, hr - left, ht - bottom);
  }
  // An arm's sides and tip move in by d; it still joins the moved rectangle.
  for (const DomainArm& arm : D.arms) {
    const Eigen::Vector4d b = arm_box(D, arm);
    // Box entry k is a u line (k even) or a v line; the one the arm joins
    // the rectangle by is the rectangle's moved side.
    const int joined = arm.side == DomainSide::Bottom ? 3 : arm.side == DomainSide::Top ? 1 : arm.side == DomainSide::Left ? 2 : 0;
    const std::array<double, 4> joined_value{right, top, left, bottom};
    Eigen::Vector4d inset;
    for (int k = 0; k < 4; ++k)
      inset(k) = k == joined ? joined_value[static_cast<std::size_t>(k)] : place(k % 2, b(k) + (k < 2 ? d : -d));
    inset -= Eigen::Vector4d(left, bottom, left, bottom);
    out.domain.arms.push_back(arm_from_box(arm.side, inset, out.domain.width, out.domain.height));
  }
  // The inset domain, shifted so that its outer rectangle starts at (0, 0).
  for (Eigen::Index v = 0; v < out.uv.rows(); ++v) out.uv.row(v) -= Eigen::RowVector2d(left, bottom);

  // Tiny edges left where two cut lines cross inside a triangle or pass
  // close to a vertex: collapsed (vertices on the cut lines stay put).
  {
    std::vector<char> pinned(static_cast<std::size_t>(out.uv.rows()), 0);
    for (Eigen::Index v = 0; v < out.uv.rows(); ++v) {
      const auto on = on_domain_lines(out.domain, out.uv.row(v).transpose());
      pinned[static_cast<std::size_t>(v)] = on[0] || on[1];
    }
    double mean3 = 0.0;
    for (Eigen::Index f = 0; f < out.mesh.F.rows(); ++f) mean3 += (out.mesh.V.row(out.mesh.F(f, 0)) - out.mesh.V.row(out.mesh.F(f, 1))).norm();
    mean3 /= std::max<Eigen::Index>(1, out.mesh.F.rows());
    collapse_short_edges(out.mesh, out.uv, pinned, 0.1 * mean3);
  }
  // Keep the triangles inside, drop unused vertices.
  std::vector<int> keep;
  for (Eigen::Index f = 0; f < out.mesh.F.rows(); ++f) {
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (int k = 0; k < 3; ++k) centre += out.uv.row(out.mesh.F(f, k)).transpose() / 3.0;
    if (inside_domain(out.domain, centre)) keep.push_back(static_cast<int>(f));
  }
  std::vector<int> index(static_cast<std::size_t>(out.mesh.V.rows()), -1);
  int count = 0;
  Eigen::MatrixXi F(static_cast<Eigen::Index>(keep.size()), 3);
  for (std::size_t i = 0; i < keep.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      int& id = index[static_cast<std::size_t>(out.mesh.F(keep[i], k))];
      if (id < 0) id = count++;
      F(static_cast<Eigen::Index>(i), k) = id;
    }
  Eigen::MatrixXd V(count, 3), uv(count, 2);
  for (std::size_t v = 0; v < index.size(); ++v)
    if (index[v] >= 0) V.row(index[v]) = out.mesh.V.row(static_cast<Eigen::Index>(v)), uv.row(index[v]) = out.uv.row(static_cast<Eigen::Index>(v));
  out.uv = uv;
  // The corners of the domain stay; everything else is smoothed (M0trim is
  // the zero set of a P1 field: wavy at the scale of the tets, and the thin
  // crest volumes along M's boundary would inherit the waves).
  std::vector<char> corner(static_cast<std::size_t>(count), 0);
  for (int v = 0; v < count; ++v) {
    const auto on = on_domain_lines(out.domain, uv.row(v).transpose());
    corner[static_cast<std::size_t>(v)] = on[0] && on[1];
  }
  // The sheet's connectivity is final here (smoothing moves vertices only):
  // one oriented sheet with a boundary loop per domain boundary, else no M.
  // This also lets the self-intersection test below always decide.
  const std::string name = "the inset base surface (d = " + std::to_string(d) + ")";
  const std::string problem = describe_sheet_problem(analyze_sheet(F, V.rows()), static_cast<int>(D.holes.size()) + 1, name);
  if (!problem.empty())
    throw bad_input(problem + "; another inset ('decomposition.inset') or corner points ('midsurface.corners') change the cut");
  // Smoothing moves vertices along their normals; where M0trim folds sharply
  // that can make M cross itself (the genus-3 torus of ../shared/models at 5
  // rounds), which H cannot embed: then fewer rounds, down to none.
  const mesh::TriMesh unsmoothed{V, F};
  for (int rounds = smoothing;; rounds /= 2) {
    out.mesh = unsmoothed;
    smooth_sheet(out.mesh, corner, rounds);
    out.smoothing = rounds;
    if (rounds == 0 || !sheet_self_intersects(out.mesh, name + " after " + std::to_string(rounds) + " smoothing rounds"))
      break;
  }
  return out;
}

}  // namespace igaprep::param
