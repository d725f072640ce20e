#include "igaprep/spline/fit_model_surface.h"

#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <map>

#include "igaprep/core/error.h"
#include "igaprep/spline/basis.h"
#include "igaprep/spline/evaluate.h"
#include "igaprep/spline/curve_surface.h"
#include "igaprep/spline/knot_vector.h"
#include "igaprep/spline/label_sides.h"
#include "igaprep/spline/multipatch_topology.h"
#include "model_points.h"

namespace igaprep::spline {
namespace {

using namespace detail;

// The rows of the pairs over all global points: the face's basis (rational
// where the patch is) at the pair's parameters.
Sparse pair_rows(const MultiPatch& mp, const GlobalNumbering& gn, const std::vector<SurfaceFitPair>& pairs) {
  std::vector<Eigen::Triplet<double>> t;
  std::map<std::pair<int, int>, std::vector<int>> side_points;  // each face's control points, found once
  for (size_t r = 0; r < pairs.size(); ++r) {
    const SurfaceFitPair& q = pairs[r];
    if (q.patch < 0 || q.patch >= static_cast<int>(mp.patches.size()))
      throw bad_input("fit_model_surface: a pair names patch " + std::to_string(q.patch) + ", which does not exist");
    const Patch& P = mp.patches[static_cast<size_t>(q.patch)];
    const std::array<int, 2> dirs = q.side.tangent_directions();
    auto found = side_points.find({q.patch, q.side.index()});
    if (found == side_points.end())
      found = side_points.emplace(std::make_pair(q.patch, q.side.index()), side_control_points(P, q.side)).first;
    const std::vector<int>& local = found->second;
    const int n0 = basis_count(P.knots[dirs[0]], P.degrees[dirs[0]]);
    std::array<int, 2> span{};
    std::array<Eigen::VectorXd, 2> N;
    for (int d = 0; d < 2; ++d) {
      const auto& U = P.knots[static_cast<size_t>(dirs[d])];
      const int p = P.degrees[static_cast<size_t>(dirs[d])];
      span[d] = find_span(U, p, q.uv[d]);
      N[d] = basis_functions(U, p, span[d], q.uv[d]);
    }
    const int p0 = P.degrees[dirs[0]], p1 = P.degrees[dirs[1]];
    std::vector<std::pair<int, double>> row;
    double sum = 0.0;
    for (int j = 0; j <= p1; ++j)
      for (int i = 0; i <= p0; ++i) {
        const int l = local[static_cast<size_t>((span[0] - p0 + i) + n0 * (span[1] - p1 + j))];
        const double w = N[0][i] * N[1][j] * (P.rational() ? P.weights[l] : 1.0);
        row.emplace_back(gn.global[static_cast<size_t>(q.patch)][static_cast<size_t>(l)], w);
        sum += w;
      }
    for (const auto& [g, w] : row) t.emplace_back(static_cast<int>(r), g, w / sum);
  }
  Sparse A(static_cast<int>(pairs.size()), gn.count);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

// Unique neighbour pairs (a < b) of the faces' control nets.
std::vector<std::pair<int, int>> face_net_edges(const MultiPatch& mp, const GlobalNumbering& gn, const Faces& faces) {
  std::vector<std::pair<int, int>> e;
  for (const auto& [patch, side] : faces) {
    const Patch& P = mp.patches[static_cast<size_t>(patch)];
    const std::array<int, 2> dirs = side.tangent_directions();
    const std::vector<int> local = side_control_points(P, side);
    const int n0 = basis_count(P.knots[dirs[0]], P.degrees[dirs[0]]);
    const int n1 = static_cast<int>(local.size()) / n0;
    auto g = [&](int i, int j) { return gn.global[static_cast<size_t>(patch)][static_cast<size_t>(local[static_cast<size_t>(i + n0 * j)])]; };
    for (int j = 0; j < n1; ++j)
      for (int i = 0; i < n0; ++i) {
        if (i + 1 < n0) e.emplace_back(std::minmax(g(i, j), g(i + 1, j)));
        if (j + 1 < n1) e.emplace_back(std::minmax(g(i, j), g(i, j + 1)));
      }
  }
  std::sort(e.begin(), e.end());
  e.erase(std::unique(e.begin(), e.end()), e.end());
  return e;
}

// Rows of the free points over all points: a point minus the mean of its
// face-net neighbours.
Sparse umbrella_rows(const std::vector<std::pair<int, int>>& edges, const Columns& c, int points) {
  std::vector<int> valence(static_cast<size_t>(points), 0);
  for (const auto& [a, b] : edges) {
    ++valence[static_cast<size_t>(a)];
    ++valence[static_cast<size_t>(b)];
  }
  std::vector<Eigen::Triplet<double>> t;
  for (size_t k = 0; k < c.point.size(); ++k) t.emplace_back(static_cast<int>(k), c.point[k], 1.0);
  auto add = [&](int from, int to) {
    const int row = c.of_point[static_cast<size_t>(from)];
    if (row >= 0) t.emplace_back(row, to, -1.0 / valence[static_cast<size_t>(from)]);
  };
  for (const auto& [a, b] : edges) {
    add(a, b);
    add(b, a);
  }
  Sparse L(static_cast<int>(c.point.size()), points);
  L.setFromTriplets(t.begin(), t.end());
  return L;
}

// The columns of A that belong to free points, in column order.
Sparse free_part(const Sparse& A, const Columns& c) {
  std::vector<Eigen::Triplet<double>> t;
  for (int k = 0; k < A.outerSize(); ++k)
    for (Sparse::InnerIterator it(A, k); it; ++it) {
      const int col = c.of_point[static_cast<size_t>(it.col())];
      if (col >= 0) t.emplace_back(static_cast<int>(it.row()), col, it.value());
    }
  Sparse out(A.rows(), static_cast<int>(c.point.size()));
  out.setFromTriplets(t.begin(), t.end());
  return out;
}

// The unit outward normal of the faces at each free point: each face's
// normal at its points' Greville parameters, turned outward of its patch
// (by the majority of its points, as a folded patch turns some), summed
// over the faces holding the point.
Eigen::MatrixXd free_point_normals(const MultiPatch& mp, const GlobalNumbering& gn, const Faces& faces,
                                   const Columns& c) {
  Eigen::MatrixXd n = Eigen::MatrixXd::Zero(static_cast<int>(c.point.size()), 3);
  for (const auto& [patch, side] : faces) {
    const Patch& P = mp.patches[static_cast<size_t>(patch)];
    const std::array<int, 2> dirs = side.tangent_directions();
    const std::vector<int> local = side_control_points(P, side);
    const std::vector<double> g0 = greville_abscissae(P.knots[dirs[0]], P.degrees[dirs[0]]);
    const std::vector<double> g1 = greville_abscissae(P.knots[dirs[1]], P.degrees[dirs[1]]);
    const int d = side.direction();
    const auto& Ud = P.knots[static_cast<size_t>(d)];
    const double end = side.parameter() ? Ud[Ud.size() - 1] : Ud.front();
    std::vector<Eigen::Vector3d> normal(local.size());
    int outward = 0;
    for (size_t k = 0; k < local.size(); ++k) {
      Eigen::Vector3d uvw;
      uvw[dirs[0]] = g0[k % g0.size()];
      uvw[dirs[1]] = g1[k / g0.size()];
      uvw[d] = end;
      const Eigen::Matrix3d J = evaluate_jacobian(P, uvw);
      normal[k] = J.col(dirs[0]).cross(J.col(dirs[1]));
      const double norm = normal[k].norm();
      if (norm > 0.0) normal[k] /= norm;
      const Eigen::Vector3d out = side.parameter() ? Eigen::Vector3d(J.col(d)) : Eigen::Vector3d(-J.col(d));
      outward += normal[k].dot(out) >= 0.0 ? 1 : -1;
    }
    for (size_t k = 0; k < local.size(); ++k) {
      const int col = c.of_point[static_cast<size_t>(gn.global[static_cast<size_t>(patch)][static_cast<size_t>(local[k])])];
      if (col >= 0) n.row(col) += (outward >= 0 ? 1.0 : -1.0) * normal[k].transpose();
    }
  }
  for (int i = 0; i < n.rows(); ++i) {
    const double norm = n.row(i).norm();
    if (norm > 0.0) n.row(i) /= norm;
  }
  return n;
}

// The pairs' rows over the free points' normal offsets: three rows per pair
// (x, y, z), each free column scaled by that point's normal component.
Sparse normal_offset_rows(const Sparse& Au, const Eigen::MatrixXd& normals) {
  std::vector<Eigen::Triplet<double>> t;
  for (int k = 0; k < Au.outerSize(); ++k)
    for (Sparse::InnerIterator it(Au, k); it; ++it)
      for (int x = 0; x < 3; ++x)
        t.emplace_back(3 * static_cast<int>(it.row()) + x, static_cast<int>(it.col()), it.value() * normals(it.col(), x));
  Sparse B(3 * Au.rows(), Au.cols());
  B.setFromTriplets(t.begin(), t.end());
  return B;
}

double rms(const Eigen::MatrixXd& r) { return r.rows() ? std::sqrt(r.squaredNorm() / r.rows()) : 0.0; }

Eigen::MatrixXd pair_targets(const std::vector<SurfaceFitPair>& pairs) {
  Eigen::MatrixXd T(static_cast<int>(pairs.size()), 3);
  for (size_t r = 0; r < pairs.size(); ++r) T.row(static_cast<int>(r)) = pairs[r].target.transpose();
  return T;
}

}  // namespace

SurfaceFitResult fit_model_surface(MultiPatch& mp, int surface, const SurfaceFitPairsFn& pairs,
                                   const std::vector<std::pair<int, Side>>& fixed_sides,
                                   const SurfaceFitOptions& options) {
  SurfaceFitResult r;
  const Faces faces = sides_on_surface(mp, surface);
  if (faces.empty()) return r;
  const GlobalNumbering gn = global_numbering(mp);
  std::vector<char> on_faces(static_cast<size_t>(gn.count), 0), held(static_cast<size_t>(gn.count), 0);
  mark_faces(mp, gn, faces, on_faces);
  mark_faces(mp, gn, faces_of(mp, [&](int label) { return label != surface; }), held);
  mark_faces(mp, gn, fixed_sides, held);
  const Columns c = free_columns(on_faces, held);
  r.moved_points = static_cast<int>(c.point.size());
  if (c.point.empty()) return r;
  const Sparse L = free_part(umbrella_rows(face_net_edges(mp, gn, faces), c, gn.count), c);
  const Sparse LtL = Sparse(L.transpose()) * L;
  const Eigen::MatrixXd normals = free_point_normals(mp, gn, faces, c);
  const Eigen::MatrixXd X0 = global_points(mp, gn);
  Eigen::MatrixXd X = X0;
  std::vector<SurfaceFitPair> p = pairs(mp);
  for (int it = 0;; ++it) {
    const Sparse A = pair_rows(mp, gn, p);
    const Eigen::MatrixXd T = pair_targets(p);
    const double now = rms(T - A * X);
    const double before = r.rms.empty() ? 0.0 : r.rms.back();
    r.rms.push_back(now);
    if (it == options.iterations || p.empty()) break;
    if (it > 0 && std::abs(before - now) < options.stop_improvement * before) break;
    // Solve for the offsets from X0 (not from X), so the fairing term sees the whole move.
    const Sparse B = normal_offset_rows(free_part(A, c), normals);
    const double lambda = options.smoothing * double(A.rows()) / double(c.point.size());
    const Sparse N = Sparse(B.transpose()) * B + lambda * LtL;
    Eigen::SimplicialLDLT<Sparse> solver(N);
    if (solver.info() != Eigen::Success) throw internal_error("fit_model_surface: the normal equations did not factorize");
    const Eigen::MatrixXd residual = Eigen::MatrixXd(T - A * X0).transpose();  // 3 x pairs: x, y, z per pair
    const Eigen::VectorXd offset =
        solver.solve(Eigen::VectorXd(B.transpose() * Eigen::Map<const Eigen::VectorXd>(residual.data(), residual.size())));
    X = X0;
    for (size_t k = 0; k < c.point.size(); ++k) X.row(c.point[k]) += offset[static_cast<int>(k)] * normals.row(static_cast<int>(k));
    scatter(X, gn, mp);
    ++r.iterations;
    p = pairs(mp);
  }
  r.max_move = (X - X0).rowwise().norm().maxCoeff();
  return r;
}

}  // namespace igaprep::spline
