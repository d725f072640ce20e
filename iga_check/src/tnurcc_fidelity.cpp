#include "igaprep/iga_check/tnurcc_fidelity.h"

#include <Eigen/Dense>
#include <algorithm>

#include "igaprep/core/error.h"
#include "surface_distance.h"

namespace igaprep::iga_check {
namespace {

struct Matches {
  std::vector<spline::FitPair> to_mesh, to_limit;  // limit -> mesh, mesh -> limit
  std::vector<double> to_mesh_distance, to_limit_distance;
  std::vector<Eigen::Vector3d> limit_points;  // of the limit -> mesh pairs
};

void limit_to_mesh(const spline::Cage& cage, const mesh::TriMesh& mesh, const LimitFidelityOptions& o, Matches& m) {
  const detail::Triangles tris = detail::mesh_triangles(mesh.V, mesh.F);
  detail::Tree tree(tris.begin(), tris.end());
  tree.accelerate_distance_queries();
  const std::vector<spline::LimitLocation> at = spline::face_grid(cage, o.samples_per_face, false);
  const Eigen::MatrixXd X = spline::limit_stencils(cage, at, spline::values_only(o.limit)).value * cage.points;
  for (size_t i = 0; i < at.size(); ++i) {
    const Eigen::Vector3d x = X.row(static_cast<int>(i)).transpose();
    const Eigen::Vector3d q = detail::vec(tree.closest_point(detail::pt(x)));
    m.to_mesh.push_back({at[i], q});
    m.to_mesh_distance.push_back((q - x).norm());
    m.limit_points.push_back(x);
  }
}

// The limit surface as triangles, with the location of each triangle's corners.
struct Tessellation {
  detail::Triangles triangles;
  std::vector<std::array<spline::LimitLocation, 3>> corners;
};

Tessellation tessellate(const spline::Cage& cage, const LimitFidelityOptions& o) {
  const int n = o.tessellation_per_face + 1;
  const std::vector<spline::LimitLocation> at = spline::face_grid(cage, n, true);
  const Eigen::MatrixXd X = spline::limit_stencils(cage, at, spline::values_only(o.limit)).value * cage.points;
  Tessellation t;
  for (size_t f = 0; f < cage.faces.size(); ++f)
    for (int j = 0; j + 1 < n; ++j)
      for (int i = 0; i + 1 < n; ++i) {
        const int a = static_cast<int>(f) * n * n + i + n * j, b = a + 1, c = a + n, d = c + 1;
        for (const auto& tri : {std::array<int, 3>{{a, b, d}}, std::array<int, 3>{{a, d, c}}}) {
          auto P = [&](int r) { return detail::pt(X.row(r).transpose()); };
          t.triangles.emplace_back(P(tri[0]), P(tri[1]), P(tri[2]));
          t.corners.push_back({{at[tri[0]], at[tri[1]], at[tri[2]]}});
        }
      }
  return t;
}

void mesh_to_limit(const spline::Cage& cage, const mesh::TriMesh& mesh, const LimitFidelityOptions& o, Matches& m) {
  const Tessellation t = tessellate(cage, o);
  detail::Tree tree(t.triangles.begin(), t.triangles.end());
  tree.accelerate_distance_queries();
  std::vector<spline::LimitLocation> guess(mesh.V.rows());
  for (int v = 0; v < mesh.V.rows(); ++v) {
    const auto hit = tree.closest_point_and_primitive(detail::pt(mesh.V.row(v).transpose()));
    const size_t k = static_cast<size_t>(hit.second - t.triangles.cbegin());
    const Eigen::Vector2d bc = detail::barycentric(t.triangles[k], hit.first);
    const auto& c = t.corners[k];
    const double w0 = 1.0 - bc[0] - bc[1];
    guess[v] = {c[0].face, std::clamp(w0 * c[0].s + bc[0] * c[1].s + bc[1] * c[2].s, 0.0, 1.0),
                std::clamp(w0 * c[0].t + bc[0] * c[1].t + bc[1] * c[2].t, 0.0, 1.0)};
  }
  // One Gauss-Newton step on the limit surface, kept inside the face.
  const spline::LimitStencils st = spline::limit_stencils(cage, guess, o.limit);
  const Eigen::MatrixXd X = st.value * cage.points, Xs = st.ds * cage.points, Xt = st.dt * cage.points;
  std::vector<spline::LimitLocation> stepped = guess;
  for (int v = 0; v < mesh.V.rows(); ++v) {
    Eigen::Matrix<double, 3, 2> J;
    J.col(0) = Xs.row(v).transpose();
    J.col(1) = Xt.row(v).transpose();
    const Eigen::Vector3d r = mesh.V.row(v).transpose() - X.row(v).transpose();
    const Eigen::Vector2d d = (J.transpose() * J).ldlt().solve(J.transpose() * r);
    if (!d.allFinite()) continue;
    stepped[v].s = std::clamp(guess[v].s + d[0], 0.0, 1.0);
    stepped[v].t = std::clamp(guess[v].t + d[1], 0.0, 1.0);
  }
  const Eigen::MatrixXd Y = spline::limit_stencils(cage, stepped, spline::values_only(o.limit)).value * cage.points;
  for (int v = 0; v < mesh.V.rows(); ++v) {
    const Eigen::Vector3d p = mesh.V.row(v).transpose();
    const double before = (X.row(v).transpose() - p).norm(), after = (Y.row(v).transpose() - p).norm();
    m.to_limit.push_back({after < before ? stepped[v] : guess[v], p});
    m.to_limit_distance.push_back(std::min(before, after));
  }
}

Matches match(const spline::Cage& cage, const mesh::TriMesh& mesh, const LimitFidelityOptions& o) {
  if (mesh.F.rows() == 0) throw bad_input("T-NURCC fidelity: the surface has no triangles");
  if (o.samples_per_face < 1 || o.tessellation_per_face < 1)
    throw bad_input("T-NURCC fidelity: samples_per_face and tessellation_per_face must be >= 1");
  Matches m;
  limit_to_mesh(cage, mesh, o, m);
  mesh_to_limit(cage, mesh, o, m);
  return m;
}

}  // namespace

LimitFidelity limit_fidelity(const spline::Cage& cage, const mesh::TriMesh& mesh, double diagonal,
                             const LimitFidelityOptions& options) {
  if (!(diagonal > 0.0)) diagonal = mesh_diagonal(mesh);
  const Matches m = match(cage, mesh, options);
  LimitFidelity f;
  std::vector<Eigen::Vector3d> vertices;
  for (const auto& p : m.to_limit) vertices.push_back(p.target);
  f.limit_to_mesh = detail::summarize(m.to_mesh_distance, m.limit_points, diagonal);
  f.mesh_to_limit = detail::summarize(m.to_limit_distance, vertices, diagonal);
  return f;
}

std::vector<spline::FitPair> limit_mesh_pairs(const spline::Cage& cage, const mesh::TriMesh& mesh,
                                              const LimitFidelityOptions& options) {
  Matches m = match(cage, mesh, options);
  m.to_mesh.insert(m.to_mesh.end(), m.to_limit.begin(), m.to_limit.end());
  return m.to_mesh;
}

}  // namespace igaprep::iga_check
