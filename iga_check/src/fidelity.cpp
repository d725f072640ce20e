#include "igaprep/iga_check/fidelity.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "igaprep/core/error.h"
#include "igaprep/core/union_find.h"
#include "igaprep/spline/curve_surface.h"
#include "igaprep/spline/evaluate.h"
#include "igaprep/spline/knot_vector.h"
#include "surface_distance.h"

namespace igaprep::iga_check {

namespace {

using detail::pt;
using detail::summarize;
using detail::Tree;
using detail::Triangles;

// n points per element in each direction, shared element ends once.
std::vector<double> element_grid(const std::vector<double>& U, int n) {
  const std::vector<double> brk = spline::unique_knots(U);
  std::vector<double> out;
  for (size_t e = 0; e + 1 < brk.size(); ++e)
    for (int i = (e == 0 ? 0 : 1); i < n; ++i) out.push_back(brk[e] + (brk[e + 1] - brk[e]) * i / (n - 1));
  return out;
}

struct Face {
  spline::Surface surface;
  std::array<std::pair<double, double>, 2> domain;
  FaceDistance distance;  // its place in the model; max filled by the spline -> mesh pass
};

// Gauss-Newton (with a tiny Levenberg term for collapsed edges) for the point
// of the face nearest x, from the parameter guess uv; returns the distance.
double project(const Face& f, const Eigen::Vector3d& x, Eigen::Vector2d uv, int iterations) {
  double best = (spline::evaluate_point(f.surface, uv) - x).norm();
  for (int it = 0; it < iterations; ++it) {
    const Eigen::Vector3d r = x - spline::evaluate_point(f.surface, uv);
    const Eigen::Matrix<double, 3, 2> J = spline::evaluate_jacobian(f.surface, uv);
    Eigen::Matrix2d A = J.transpose() * J;
    A.diagonal().array() += 1e-12 * (A.trace() + 1e-300);
    Eigen::Vector2d step = A.ldlt().solve(J.transpose() * r);
    if (!step.allFinite()) break;
    Eigen::Vector2d next = uv + step;
    for (int d = 0; d < 2; ++d) next[d] = std::clamp(next[d], f.domain[d].first, f.domain[d].second);
    const double dist = (spline::evaluate_point(f.surface, next) - x).norm();
    if (dist > best) break;  // no progress: keep the best point
    const double moved = (next - uv).norm();
    uv = next;
    best = dist;
    if (moved < 1e-14) break;
  }
  return best;
}

}  // namespace

double mesh_diagonal(const mesh::TriMesh& m) {
  if (m.V.rows() == 0) return 0.0;
  return (m.V.colwise().maxCoeff() - m.V.colwise().minCoeff()).norm();
}

std::vector<UncoveredRegion> uncovered_regions(const mesh::TriMesh& mesh, const std::vector<double>& distance,
                                               double limit) {
  const int n = static_cast<int>(mesh.V.rows());
  if (static_cast<int>(distance.size()) != n)
    throw bad_input("uncovered_regions: " + std::to_string(distance.size()) + " distances for " + std::to_string(n) +
                    " vertices");
  auto far = [&](int v) { return distance[static_cast<size_t>(v)] > limit; };
  UnionFind sets(n);
  for (int f = 0; f < mesh.F.rows(); ++f)
    for (int e = 0; e < 3; ++e) {
      const int a = mesh.F(f, e), b = mesh.F(f, (e + 1) % 3);
      if (far(a) && far(b)) sets.unite(a, b);
    }
  std::map<int, UncoveredRegion> by_root;
  for (int v = 0; v < n; ++v) {
    if (!far(v)) continue;
    UncoveredRegion& r = by_root[sets.find(v)];
    const Eigen::Vector3d x = mesh.V.row(v).transpose();
    ++r.vertices;
    r.centroid += x;
    if (r.vertices == 1 || distance[static_cast<size_t>(v)] > r.max) {
      r.max = distance[static_cast<size_t>(v)];
      r.farthest = x;
    }
  }
  std::vector<UncoveredRegion> out;
  for (auto& [root, r] : by_root) {
    r.centroid /= r.vertices;
    out.push_back(r);
  }
  std::stable_sort(out.begin(), out.end(), [](const UncoveredRegion& a, const UncoveredRegion& b) { return a.max > b.max; });
  return out;
}

double model_diagonal(const spline::MultiPatch& mp) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const spline::Patch& p : mp.patches) {
    std::array<std::vector<double>, 3> params;
    for (int d = 0; d < 3; ++d) params[d] = element_grid(p.knots[d], 3);
    const Eigen::MatrixXd X = spline::evaluate_grid_points(p, spline::grid_basis(p, params, 0));
    for (int i = 0; i < X.rows(); ++i) {
      lo = lo.cwiseMin(X.row(i).transpose());
      hi = hi.cwiseMax(X.row(i).transpose());
    }
  }
  return mp.patches.empty() ? 0.0 : (hi - lo).norm();
}

std::vector<SurfaceFidelity> fidelity(const spline::MultiPatch& mp, const std::vector<mesh::TriMesh>& surfaces,
                                      double diagonal, const FidelityOptions& options) {
  if (options.samples_per_element < 2 || options.tessellation_per_element < 1)
    throw bad_input("fidelity: samples_per_element must be >= 2 and tessellation_per_element >= 1");
  if (!(diagonal > 0.0)) diagonal = model_diagonal(mp);
  if (!(diagonal > 0.0)) throw bad_input("fidelity: the model has no extent");
  std::vector<SurfaceFidelity> out;
  for (size_t si = 0; si < surfaces.size(); ++si) {
    if (options.only_surface >= 0 && static_cast<int>(si) != options.only_surface) continue;
    const mesh::TriMesh& tm = surfaces[si];
    SurfaceFidelity sf;
    sf.surface = static_cast<int>(si);
    if (si < mp.labels.size()) sf.label = mp.labels[si];
    std::vector<Face> faces;
    auto add_face = [&](int patch, spline::Side side, bool interface) {
      if (patch < 0 || patch >= static_cast<int>(mp.patches.size()))
        throw bad_input("fidelity: side refers to patch " + std::to_string(patch) + ", which does not exist");
      Face f;
      f.surface = spline::boundary_surface(mp.patches[patch], side);
      f.distance.patch = patch;
      f.distance.side = side;
      f.distance.interface = interface;
      for (int d = 0; d < 2; ++d) {
        const auto& U = f.surface.knots[d];
        const int p = f.surface.degrees[d];
        f.domain[d] = {U[p], U[U.size() - p - 1]};
      }
      faces.push_back(std::move(f));
    };
    for (const auto& b : mp.boundaries)
      if (b.label == static_cast<int>(si)) {
        add_face(b.patch, b.side, false);
        ++sf.boundary_faces;
      }
    for (const auto& itf : mp.interfaces)
      if (itf.surface == static_cast<int>(si)) {
        add_face(itf.patch_a, itf.side_a, true);
        ++sf.interface_faces;
      }
    if (faces.empty()) continue;
    if (tm.F.rows() == 0) throw bad_input("fidelity: input surface " + std::to_string(si) + " has no triangles");

    // spline -> mesh
    const Triangles mesh_tris = detail::mesh_triangles(tm.V, tm.F);
    Tree mesh_tree(mesh_tris.begin(), mesh_tris.end());
    mesh_tree.accelerate_distance_queries();
    std::vector<double> d1;
    std::vector<Eigen::Vector3d> w1;
    for (Face& f : faces) {
      std::array<std::vector<double>, 2> params{{element_grid(f.surface.knots[0], options.samples_per_element),
                                                 element_grid(f.surface.knots[1], options.samples_per_element)}};
      const spline::GridEvaluation ev = spline::evaluate_grid(f.surface, params, 0);
      for (int i = 0; i < ev.points.rows(); ++i) {
        const Eigen::Vector3d x = ev.points.row(i).transpose();
        const double d = std::sqrt(mesh_tree.squared_distance(pt(x)));
        d1.push_back(d);
        w1.push_back(x);
        if (d > f.distance.max || i == 0) {
          f.distance.max = d;
          f.distance.max_location = x;
        }
      }
      sf.faces.push_back(f.distance);
    }
    sf.spline_to_mesh = summarize(d1, w1, diagonal);

    // mesh -> spline: tessellate the faces, remember each triangle's parameters.
    Triangles tess;
    std::vector<std::pair<int, std::array<Eigen::Vector2d, 3>>> tess_uv;
    for (size_t fi = 0; fi < faces.size(); ++fi) {
      const Face& f = faces[fi];
      std::array<std::vector<double>, 2> params{
          {element_grid(f.surface.knots[0], options.tessellation_per_element + 1),
           element_grid(f.surface.knots[1], options.tessellation_per_element + 1)}};
      const spline::GridEvaluation ev = spline::evaluate_grid(f.surface, params, 0);
      const int nu = static_cast<int>(params[0].size()), nv = static_cast<int>(params[1].size());
      for (int j = 0; j + 1 < nv; ++j)
        for (int i = 0; i + 1 < nu; ++i) {
          const int a = i + nu * j, b = a + 1, c = a + nu, d = c + 1;
          const Eigen::Vector2d ua(params[0][i], params[1][j]), ub(params[0][i + 1], params[1][j]),
              uc(params[0][i], params[1][j + 1]), ud(params[0][i + 1], params[1][j + 1]);
          auto P = [&](int r) { return pt(ev.points.row(r).transpose()); };
          tess.emplace_back(P(a), P(b), P(d));
          tess_uv.push_back({static_cast<int>(fi), {ua, ub, ud}});
          tess.emplace_back(P(a), P(d), P(c));
          tess_uv.push_back({static_cast<int>(fi), {ua, ud, uc}});
        }
    }
    Tree tess_tree(tess.begin(), tess.end());
    tess_tree.accelerate_distance_queries();
    std::vector<double> d2;
    std::vector<Eigen::Vector3d> w2;
    for (int v = 0; v < tm.V.rows(); ++v) {
      const Eigen::Vector3d x = tm.V.row(v).transpose();
      const auto hit = tess_tree.closest_point_and_primitive(pt(x));
      const size_t t = static_cast<size_t>(hit.second - tess.cbegin());
      // Barycentric coordinates of the closest point give the parameter guess.
      const Eigen::Vector2d bc = detail::barycentric(tess[t], hit.first);
      const double s = bc[0], u = bc[1];
      const auto& uvs = tess_uv[t].second;
      const Eigen::Vector2d guess = (1.0 - s - u) * uvs[0] + s * uvs[1] + u * uvs[2];
      const double dist = project(faces[tess_uv[t].first], x, guess, options.newton_iterations);
      d2.push_back(dist);
      w2.push_back(x);
    }
    sf.mesh_to_spline = summarize(d2, w2, diagonal);
    sf.vertex_distance = std::move(d2);
    out.push_back(std::move(sf));
  }
  return out;
}

}  // namespace igaprep::iga_check
