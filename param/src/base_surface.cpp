#include "igaprep/param/base_surface.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <unordered_map>

#include <Eigen/Geometry>

#include "igaprep/core/error.h"
#include "igaprep/param/harmonic_field.h"
#include "igaprep/param/sheet_topology.h"
#include "igaprep/param/stiffness_matrix.h"
#include "igaprep/param/tet_topology.h"
#include "igaprep/param/trace_gradient.h"

namespace igaprep::param {
namespace {

// A feature of the domain boundary: a side (segment a-b) or a hole corner (point a).
struct Feature {
  Eigen::Vector2d a, b;
  bool point = false;
  std::vector<int> corners;  // ids of the domain vertices it contains
};

std::vector<Feature> domain_features(const RectilinearDomain& d) {
  std::vector<Feature> fs;
  auto add_box = [&](const Eigen::Vector4d& box, int id0, bool hole) {
    const Eigen::Vector2d c[4] = {{box(0), box(1)}, {box(2), box(1)}, {box(2), box(3)}, {box(0), box(3)}};
    for (int k = 0; k < 4; ++k) fs.push_back({c[k], c[(k + 1) % 4], false, {id0 + k, id0 + (k + 1) % 4}});
    if (hole)
      for (int k = 0; k < 4; ++k) fs.push_back({c[k], c[k], true, {id0 + k}});
  };
  add_box(Eigen::Vector4d(0.0, 0.0, d.width, d.height), 0, false);
  for (std::size_t h = 0; h < d.holes.size(); ++h) add_box(d.holes[h], 4 + 4 * static_cast<int>(h), true);
  return fs;
}

// Distance to a side counts only where the foot of the perpendicular is inside
// it (the hole corners cover the rest); outer sides are clamped.
double feature_distance(const Feature& f, const Eigen::Vector2d& p, bool clamp) {
  if (f.point) return (p - f.a).norm();
  const Eigen::Vector2d d = f.b - f.a;
  double t = (p - f.a).dot(d) / d.squaredNorm();
  if (t < 0.0 || t > 1.0) {
    if (!clamp) return std::numeric_limits<double>::infinity();
    t = std::clamp(t, 0.0, 1.0);
  }
  return (p - (f.a + t * d)).norm();
}

bool adjacent(const Feature& x, const Feature& y) {
  for (int a : x.corners)
    for (int b : y.corners)
      if (a == b) return true;
  return false;
}

std::uint64_t key2(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint64_t>(b);
}

}  // namespace

std::vector<int> medial_axis_vertices(const mesh::TriMesh& sheet, const Eigen::MatrixXd& uv,
                                      const RectilinearDomain& domain, const std::vector<char>& boundary) {
  const std::vector<Feature> fs = domain_features(domain);
  const Eigen::Index n = sheet.V.rows();
  std::vector<int> nearest(static_cast<std::size_t>(n), -1);
  std::vector<double> depth(static_cast<std::size_t>(n), 0.0);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector2d p = uv.row(i).transpose();
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < fs.size(); ++k) {
      const double d = feature_distance(fs[k], p, k < 4);
      if (d < best) {
        best = d;
        nearest[static_cast<std::size_t>(i)] = static_cast<int>(k);
      }
    }
    depth[static_cast<std::size_t>(i)] = best;
  }
  std::set<int> medial;
  for (int f = 0; f < sheet.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = sheet.F(f, k), b = sheet.F(f, (k + 1) % 3);
      const int fa = nearest[static_cast<std::size_t>(a)], fb = nearest[static_cast<std::size_t>(b)];
      if (fa < 0 || fb < 0 || fa == fb || adjacent(fs[static_cast<std::size_t>(fa)], fs[static_cast<std::size_t>(fb)]))
        continue;
      if (!boundary[static_cast<std::size_t>(a)]) medial.insert(a);
      if (!boundary[static_cast<std::size_t>(b)]) medial.insert(b);
    }
  if (medial.empty()) {
    int best = -1;
    for (Eigen::Index i = 0; i < n; ++i)
      if (!boundary[static_cast<std::size_t>(i)] && (best < 0 || depth[static_cast<std::size_t>(i)] > depth[static_cast<std::size_t>(best)]))
        best = static_cast<int>(i);
    if (best < 0) throw bad_input("base surface: M0trim has no interior vertex");
    medial.insert(best);
  }
  return {medial.begin(), medial.end()};
}

Eigen::VectorXd base_field(const mesh::TriMesh& sheet, const std::vector<int>& medial, const std::vector<int>& boundary) {
  HarmonicSolver solver(tri_cotan_laplacian(sheet.V, sheet.F), {medial, boundary});
  return solver.solve({1.0, 0.0});
}

BaseSurface trim_base_surface(const mesh::TriMesh& sheet, const Eigen::VectorXd& b_in, double m0,
                              const Eigen::MatrixXd& uv) {
  if (!(m0 > 0.0 && m0 < 1.0)) throw bad_input("base surface: m0 must lie in (0, 1), got " + std::to_string(m0));
  BaseSurface out;
  out.m0 = m0;
  out.b = b_in;
  Eigen::VectorXd s = b_in.array() - m0;
  // Snap values that would cut an edge within 1 % of a vertex.
  for (int f = 0; f < sheet.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = sheet.F(f, k), c = sheet.F(f, (k + 1) % 3);
      if (!(s(a) * s(c) < 0.0)) continue;
      const double t = s(a) / (s(a) - s(c));
      if (t < 0.01) s(a) = 0.0;
      if (t > 0.99) s(c) = 0.0;
    }
  std::unordered_map<std::uint64_t, int> vid;
  std::vector<std::array<int, 2>> edges;
  std::vector<double> ts;
  auto vertex = [&](int a, int c) {
    if (a > c) std::swap(a, c);
    auto it = vid.find(key2(a, c));
    if (it != vid.end()) return it->second;
    edges.push_back({a, c});
    ts.push_back(a == c ? 0.0 : s(a) / (s(a) - s(c)));
    return vid[key2(a, c)] = static_cast<int>(edges.size()) - 1;
  };
  std::vector<std::array<int, 3>> tris;
  for (int f = 0; f < sheet.F.rows(); ++f) {
    std::vector<int> poly;
    for (int k = 0; k < 3; ++k) {
      const int a = sheet.F(f, k), c = sheet.F(f, (k + 1) % 3);
      if (s(a) >= 0.0) poly.push_back(vertex(a, a));
      if (s(a) * s(c) < 0.0) poly.push_back(vertex(a, c));
    }
    bool positive = false;
    for (int k = 0; k < 3; ++k) positive = positive || s(sheet.F(f, k)) > 0.0;
    if (poly.size() < 3 || !positive) continue;
    for (std::size_t i = 1; i + 1 < poly.size(); ++i) tris.push_back({poly[0], poly[i], poly[i + 1]});
  }
  if (tris.empty()) throw bad_input("base surface: M = {b >= m0} is empty for m0 = " + std::to_string(m0) + "; use a smaller m0");
  const Eigen::Index nv = static_cast<Eigen::Index>(edges.size());
  out.mesh.V.resize(nv, 3);
  out.uv.resize(nv, 2);
  out.source_edge.resize(nv, 2);
  out.source_t.resize(nv);
  for (Eigen::Index i = 0; i < nv; ++i) {
    const auto& e = edges[static_cast<std::size_t>(i)];
    const double t = ts[static_cast<std::size_t>(i)];
    out.source_edge(i, 0) = e[0];
    out.source_edge(i, 1) = e[1];
    out.source_t(i) = t;
    out.mesh.V.row(i) = (1.0 - t) * sheet.V.row(e[0]) + t * sheet.V.row(e[1]);
    out.uv.row(i) = (1.0 - t) * uv.row(e[0]) + t * uv.row(e[1]);
  }
  out.mesh.F.resize(static_cast<Eigen::Index>(tris.size()), 3);
  for (std::size_t f = 0; f < tris.size(); ++f)
    for (int k = 0; k < 3; ++k) out.mesh.F(static_cast<Eigen::Index>(f), k) = tris[f][k];
  return out;
}

BaseSurface base_surface(const mesh::TriMesh& sheet, const Polycube2D& pc, double m0, int expected_loops) {
  std::vector<char> is_boundary(static_cast<std::size_t>(sheet.V.rows()), 0);
  std::vector<int> boundary;
  for (const auto& L : pc.loops)
    for (int v : L.vertices) {
      is_boundary[static_cast<std::size_t>(v)] = 1;
      boundary.push_back(v);
    }
  const std::vector<int> medial = medial_axis_vertices(sheet, pc.uv, pc.domain, is_boundary);
  const Eigen::VectorXd b = base_field(sheet, medial, boundary);
  BaseSurface M = trim_base_surface(sheet, b, m0, pc.uv);
  M.medial = medial;
  SheetTopology topo = analyze_sheet(M.mesh.F, M.mesh.V.rows());
  std::string problem = describe_sheet_problem(topo, expected_loops, "the base surface M = {b >= m0}");
  if (!problem.empty()) throw bad_input(problem + " (m0 = " + std::to_string(m0) + "; try a smaller m0)");
  M.boundary_loops = topo.boundary_loops;

  // Corners: trace +grad b from each M0trim corner to b = m0, then insert the
  // end into M's nearest boundary edge.
  const TetTopology tt = build_tet_topology(sheet.F, sheet.V.rows());
  GradientTracer tracer(sheet.V, sheet.F, tt, b);
  TraceTarget target;
  target.use_iso = true;
  target.iso = m0;
  M.corner_traces_end.resize(static_cast<Eigen::Index>(4 * pc.loops.size()), 3);
  M.corners.assign(pc.loops.size(), {-1, -1, -1, -1});
  M.corner_loop.assign(pc.loops.size(), -1);
  for (std::size_t l = 0; l < pc.loops.size(); ++l) {
    for (int k = 0; k < 4; ++k) {
      const int c = pc.loops[l].vertices[static_cast<std::size_t>(pc.loops[l].corners[k])];
      const int cell = tt.vertex_cells[static_cast<std::size_t>(tt.vertex_cells_start[c])];
      Eigen::Vector4d bary = Eigen::Vector4d::Zero();
      for (int j = 0; j < 3; ++j)
        if (sheet.F(cell, j) == c) bary(j) = 1.0;
      const TraceResult r = tracer.trace(cell, bary, target);
      if (r.status != TraceStatus::Reached)
        throw internal_error("base surface: the grad b trace from corner vertex " + std::to_string(c) +
                             " ended without reaching b = m0 (" + to_string(r.status) + ")");
      M.corner_traces_end.row(static_cast<Eigen::Index>(4 * l + k)) = r.end.transpose();
      // nearest boundary edge of M
      double best = std::numeric_limits<double>::infinity();
      int bl = -1, bi = -1;
      double bt = 0.0;
      for (std::size_t ml = 0; ml < M.boundary_loops.size(); ++ml) {
        const auto& loop = M.boundary_loops[ml];
        for (std::size_t i = 0; i < loop.size(); ++i) {
          const Eigen::Vector3d a = M.mesh.V.row(loop[i]).transpose(), e = M.mesh.V.row(loop[(i + 1) % loop.size()]).transpose();
          const double t = std::clamp((r.end - a).dot(e - a) / std::max((e - a).squaredNorm(), 1e-300), 0.0, 1.0);
          const double d = (r.end - (a + t * (e - a))).norm();
          if (d < best) {
            best = d;
            bl = static_cast<int>(ml);
            bi = static_cast<int>(i);
            bt = t;
          }
        }
      }
      auto& loop = M.boundary_loops[static_cast<std::size_t>(bl)];
      const int va = loop[static_cast<std::size_t>(bi)], vb = loop[(static_cast<std::size_t>(bi) + 1) % loop.size()];
      int corner;
      if (bt < 0.05) {
        corner = va;
      } else if (bt > 0.95) {
        corner = vb;
      } else {  // split the boundary edge va -> vb and its triangle
        corner = static_cast<int>(M.mesh.V.rows());
        M.mesh.V.conservativeResize(corner + 1, 3);
        M.mesh.V.row(corner) = (1.0 - bt) * M.mesh.V.row(va) + bt * M.mesh.V.row(vb);
        M.uv.conservativeResize(corner + 1, 2);
        M.uv.row(corner) = (1.0 - bt) * M.uv.row(va) + bt * M.uv.row(vb);
        M.source_edge.conservativeResize(corner + 1, 2);
        M.source_edge.row(corner) << -1, -1;
        M.source_t.conservativeResize(corner + 1);
        M.source_t(corner) = 0.0;
        for (Eigen::Index f = 0; f < M.mesh.F.rows(); ++f)
          for (int j = 0; j < 3; ++j)
            if (M.mesh.F(f, j) == va && M.mesh.F(f, (j + 1) % 3) == vb) {
              const int w = M.mesh.F(f, (j + 2) % 3);
              M.mesh.F(f, (j + 1) % 3) = corner;
              M.mesh.F.conservativeResize(M.mesh.F.rows() + 1, 3);
              M.mesh.F.row(M.mesh.F.rows() - 1) << corner, vb, w;
              f = M.mesh.F.rows();
              break;
            }
        loop.insert(loop.begin() + bi + 1, corner);
      }
      if (M.corner_loop[l] >= 0 && M.corner_loop[l] != bl)
        throw bad_input("base surface: the corners of boundary loop " + std::to_string(l) +
                        " of M0trim move to different loops of M; try a smaller m0");
      M.corner_loop[l] = bl;
      M.corners[l][k] = corner;
    }
    std::set<int> distinct(M.corners[l].begin(), M.corners[l].end());
    if (distinct.size() != 4)
      throw bad_input("base surface: two corners of boundary loop " + std::to_string(l) +
                      " of M0trim meet on M's boundary; try a smaller m0");
  }
  return M;
}

}  // namespace igaprep::param
