#include "model_faces.h"

#include <Eigen/Dense>
#include <algorithm>
#include <string>

#include "igaprep/core/error.h"
#include "igaprep/spline/evaluate.h"
#include "igaprep/spline/knot_vector.h"

namespace igaprep::iga_check::detail {

std::vector<double> element_grid(const std::vector<double>& U, int n) {
  const std::vector<double> brk = spline::unique_knots(U);
  std::vector<double> out;
  for (size_t e = 0; e + 1 < brk.size(); ++e)
    for (int i = (e == 0 ? 0 : 1); i < n; ++i) out.push_back(brk[e] + (brk[e + 1] - brk[e]) * i / (n - 1));
  return out;
}

std::vector<ModelFace> faces_of_surface(const spline::MultiPatch& mp, int surface) {
  std::vector<ModelFace> faces;
  auto add_face = [&](int patch, spline::Side side, bool interface) {
    if (patch < 0 || patch >= static_cast<int>(mp.patches.size()))
      throw bad_input("fidelity: side refers to patch " + std::to_string(patch) + ", which does not exist");
    ModelFace f;
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
    if (b.label == surface) add_face(b.patch, b.side, false);
  for (const auto& itf : mp.interfaces)
    if (itf.surface == surface) add_face(itf.patch_a, itf.side_a, true);
  return faces;
}

std::vector<ModelFace> faces_of_surface(const spline::ExtractionModel& m, int surface) {
  std::vector<ModelFace> faces;
  auto add_face = [&](const spline::ExtractionBoundaryFace& bf, bool interface) {
    if (bf.element < 0 || bf.element >= static_cast<int>(m.elements.size()))
      throw bad_input("fidelity: a face refers to element " + std::to_string(bf.element) + ", which does not exist");
    const spline::ExtractionElement& e = m.elements[static_cast<size_t>(bf.element)];
    const spline::BezierElement be = spline::bernstein_element(m, bf.element);
    spline::Patch bezier;  // the element as a one-element patch on [0, 1]^3
    bezier.degrees = e.degrees;
    for (size_t d = 0; d < 3; ++d) {
      bezier.knots[d].assign(static_cast<size_t>(e.degrees[d] + 1), 0.0);
      bezier.knots[d].resize(static_cast<size_t>(2 * (e.degrees[d] + 1)), 1.0);
    }
    bezier.control_points = be.points;
    bezier.weights = be.weights;
    ModelFace f;
    f.surface = spline::boundary_surface(bezier, bf.side);
    f.distance.patch = e.patch;
    f.distance.element = bf.element;
    f.distance.side = bf.side;
    f.distance.interface = interface;
    f.domain = {{{0.0, 1.0}, {0.0, 1.0}}};
    faces.push_back(std::move(f));
  };
  for (const auto& bf : m.boundary_faces)
    if (bf.label == surface) add_face(bf, false);
  for (const auto& bf : m.interface_faces)
    if (bf.label == surface) add_face(bf, true);
  return faces;
}

double project_to_face(const ModelFace& f, const Eigen::Vector3d& x, Eigen::Vector2d& uv, int iterations) {
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

FaceTessellation tessellate_faces(const std::vector<ModelFace>& faces, int per_element) {
  FaceTessellation t;
  for (size_t fi = 0; fi < faces.size(); ++fi) {
    const ModelFace& f = faces[fi];
    std::array<std::vector<double>, 2> params{
        {element_grid(f.surface.knots[0], per_element + 1), element_grid(f.surface.knots[1], per_element + 1)}};
    const spline::GridEvaluation ev = spline::evaluate_grid(f.surface, params, 0);
    const int nu = static_cast<int>(params[0].size()), nv = static_cast<int>(params[1].size());
    for (int j = 0; j + 1 < nv; ++j)
      for (int i = 0; i + 1 < nu; ++i) {
        const int a = i + nu * j, b = a + 1, c = a + nu, d = c + 1;
        const Eigen::Vector2d ua(params[0][i], params[1][j]), ub(params[0][i + 1], params[1][j]),
            uc(params[0][i], params[1][j + 1]), ud(params[0][i + 1], params[1][j + 1]);
        auto P = [&](int r) { return pt(ev.points.row(r).transpose()); };
        t.triangles.emplace_back(P(a), P(b), P(d));
        t.uv.push_back({static_cast<int>(fi), {ua, ub, ud}});
        t.triangles.emplace_back(P(a), P(d), P(c));
        t.uv.push_back({static_cast<int>(fi), {ua, ud, uc}});
      }
  }
  return t;
}

FacePoint nearest_face_point(const std::vector<ModelFace>& faces, const FaceTessellation& t, const Tree& tree,
                             const Eigen::Vector3d& x, int newton_iterations) {
  const auto hit = tree.closest_point_and_primitive(pt(x));
  const size_t k = static_cast<size_t>(hit.second - t.triangles.cbegin());
  // Barycentric coordinates of the closest point give the parameter guess.
  const Eigen::Vector2d bc = barycentric(t.triangles[k], hit.first);
  const auto& uvs = t.uv[k].second;
  FacePoint out;
  out.face = t.uv[k].first;
  out.uv = (1.0 - bc[0] - bc[1]) * uvs[0] + bc[0] * uvs[1] + bc[1] * uvs[2];
  out.distance = project_to_face(faces[static_cast<size_t>(out.face)], x, out.uv, newton_iterations);
  return out;
}

}  // namespace igaprep::iga_check::detail
