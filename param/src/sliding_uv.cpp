#include "igaprep/param/sliding_uv.h"

#include <sstream>
#include <vector>

#include "igaprep/param/harmonic_field.h"
#include "igaprep/param/stiffness_matrix.h"

namespace igaprep::param {

namespace {

// u and v each harmonic, fixed only on the sides iso in them (corners are on
// two sides, so fixed in both).
Eigen::MatrixXd sliding_solution(const mesh::TriMesh& sheet, const std::vector<BoundarySegment>& segments) {
  const Eigen::Index n = sheet.V.rows();
  std::vector<std::vector<int>> fixed(2);
  Eigen::MatrixXd values = Eigen::MatrixXd::Zero(n, 2);
  std::vector<char> seen(static_cast<std::size_t>(2 * n), 0);
  for (const BoundarySegment& s : segments) {
    const int axis = s.u_iso ? 0 : 1;
    for (int v : s.vertices) {
      values(v, axis) = s.value;
      char& mark = seen[static_cast<std::size_t>(2 * v + axis)];
      if (!mark) fixed[static_cast<std::size_t>(axis)].push_back(v);
      mark = 1;
    }
  }
  const Eigen::SparseMatrix<double> L = tri_cotan_laplacian(sheet.V, sheet.F);
  Eigen::MatrixXd uv(n, 2);
  for (int axis = 0; axis < 2; ++axis)
    uv.col(axis) = HarmonicSolver(L, {fixed[static_cast<std::size_t>(axis)]}).solve_with(values.col(axis));
  return uv;
}

bool strictly_ordered(const std::vector<double>& x) {
  const double dir = x.back() > x.front() ? 1.0 : -1.0;
  for (std::size_t i = 1; i < x.size(); ++i)
    if (!(dir * (x[i] - x[i - 1]) > 0.0)) return false;
  return true;
}

}  // namespace

SlidingUv sliding_uv(const mesh::TriMesh& sheet, const Polycube2D& polycube) {
  SlidingUv out;
  const Eigen::MatrixXd sliding = sliding_solution(sheet, polycube.segments);
  std::vector<char> fixed;
  Eigen::MatrixXd boundary = boundary_uv(sheet, polycube.segments, fixed);  // arc-length positions
  for (const BoundarySegment& s : polycube.segments) {
    const int free = s.u_iso ? 1 : 0;
    // The largest share of the sliding positions that keeps the side in order
    // (the ends are the corners: equal in both).
    for (const double share : {1.0, 0.75, 0.5, 0.25, 0.0}) {
      std::vector<double> x;
      for (int v : s.vertices) x.push_back(share * sliding(v, free) + (1.0 - share) * boundary(v, free));
      x.front() = boundary(s.vertices.front(), free);
      x.back() = boundary(s.vertices.back(), free);
      if (!strictly_ordered(x) && share > 0.0) continue;
      for (std::size_t i = 0; i < x.size(); ++i) boundary(s.vertices[i], free) = x[i];
      out.min_sliding_share = std::min(out.min_sliding_share, share);
      break;
    }
  }
  out.uv = harmonic_uv(sheet, boundary, fixed, UvWeights::Cotangent);
  if (uv_jacobians(sheet, out.uv).minCoeff() <= 0.0) untangle_uv(sheet, out.uv, fixed);
  out.min_jacobian = uv_jacobians(sheet, out.uv).minCoeff();
  out.valid = out.min_jacobian > 0.0;
  if (!out.valid) {
    std::ostringstream why;
    why << "a triangle is not positively oriented (min Jacobian " << out.min_jacobian << ")";
    out.reason = why.str();
  }
  return out;
}

}  // namespace igaprep::param
