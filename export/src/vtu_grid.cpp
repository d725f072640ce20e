#include "vtu_grid.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "igaprep/core/point_merger.h"
#include "igaprep/export/vtu_bezier.h"
#include "vtu_arrays.h"
#include "igaprep/spline/evaluate.h"
#include "igaprep/spline/knot_vector.h"
#include "igaprep/spline/scaled_jacobian.h"

namespace igaprep::exporter::detail {

void share_coincident_points(Grid& g) {
  const std::size_t n = g.weights.size();
  if (n == 0) return;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (std::size_t i = 0; i < n; ++i) {
    lo = lo.cwiseMin(Eigen::Vector3d(g.points[3 * i], g.points[3 * i + 1], g.points[3 * i + 2]));
    hi = hi.cwiseMax(Eigen::Vector3d(g.points[3 * i], g.points[3 * i + 1], g.points[3 * i + 2]));
  }
  const double tol = 1e-10 * std::max((hi - lo).norm(), 1e-300);
  struct Shared {
    PointMerger merger;
    std::vector<int64_t> point;  // merger vertex -> point of the shared grid
  };
  std::map<int32_t, Shared> by_material;
  std::vector<int64_t> shared_of(n);
  std::vector<double> points, weights;
  std::vector<int32_t> material, patch;
  for (std::size_t i = 0; i < n; ++i) {
    Shared& s = by_material.try_emplace(g.point_material[i], Shared{PointMerger(tol), {}}).first->second;
    const auto [vertex, added] = s.merger.insert(Eigen::Vector3d(g.points[3 * i], g.points[3 * i + 1], g.points[3 * i + 2]));
    if (added) s.point.push_back(static_cast<int64_t>(weights.size()));
    const int64_t at = s.point[static_cast<std::size_t>(vertex)];
    if (!added && std::abs(weights[static_cast<std::size_t>(at)] - g.weights[i]) <= 1e-12 * std::abs(g.weights[i])) {
      shared_of[i] = at;
      continue;
    }
    shared_of[i] = static_cast<int64_t>(weights.size());  // new, or the same place with another weight
    points.insert(points.end(), {g.points[3 * i], g.points[3 * i + 1], g.points[3 * i + 2]});
    weights.push_back(g.weights[i]);
    material.push_back(g.point_material[i]);
    patch.push_back(g.point_patch[i]);
  }
  for (int64_t& c : g.connectivity) c = shared_of[static_cast<std::size_t>(c)];
  g.points = std::move(points);
  g.weights = std::move(weights);
  g.point_material = std::move(material);
  g.point_patch = std::move(patch);
}

int64_t add_cell(Grid& g, const spline::BezierElement& be, const std::vector<int>& vtk_of_local,
                 const std::array<int, 3>& degrees, int material, int patch, const std::array<int, 3>& index,
                 double min_scaled_jacobian) {
  const auto nb = static_cast<int64_t>(vtk_of_local.size());
  const auto base = static_cast<int64_t>(g.weights.size());
  g.points.resize(g.points.size() + 3 * static_cast<std::size_t>(nb));
  g.weights.resize(g.weights.size() + static_cast<std::size_t>(nb));
  for (int64_t b = 0; b < nb; ++b) {
    const auto at = static_cast<std::size_t>(base + vtk_of_local[static_cast<std::size_t>(b)]);
    for (int c = 0; c < 3; ++c) g.points[3 * at + static_cast<std::size_t>(c)] = be.points(b, c);
    g.weights[at] = be.weights.size() > 0 ? be.weights[b] : 1.0;
  }
  for (int64_t b = 0; b < nb; ++b) g.connectivity.push_back(base + b);
  g.offsets.push_back(static_cast<int64_t>(g.connectivity.size()));
  g.degrees.insert(g.degrees.end(), degrees.begin(), degrees.end());
  g.material.push_back(material);
  g.patch.push_back(patch);
  g.element.insert(g.element.end(), index.begin(), index.end());
  g.min_scaled_jacobian.push_back(min_scaled_jacobian);
  g.point_material.resize(g.weights.size(), material);
  g.point_patch.resize(g.weights.size(), patch);
  return base;
}

std::vector<int> vtk_hex_order(const std::array<int, 3>& deg) {
  std::vector<int> out(static_cast<std::size_t>((deg[0] + 1) * (deg[1] + 1) * (deg[2] + 1)));
  for (int k = 0; k <= deg[2]; ++k)
    for (int j = 0; j <= deg[1]; ++j)
      for (int i = 0; i <= deg[0]; ++i)
        out[static_cast<std::size_t>(i + (deg[0] + 1) * (j + (deg[1] + 1) * k))] = vtk_hex_point_index(i, j, k, deg);
  return out;
}

std::vector<double> element_min_scaled_jacobians(const spline::Patch& p) {
  // One grid evaluation of the whole patch: every element's nodes, elements
  // side by side (a shared node is evaluated for each element it belongs to).
  std::array<std::vector<double>, 3> params;
  std::array<int, 3> ne{}, nodes{};
  for (int d = 0; d < 3; ++d) {
    const std::vector<double> brk = spline::unique_knots(p.knots[d]);
    ne[d] = static_cast<int>(brk.size()) - 1;
    nodes[d] = p.degrees[d] + 1;
    for (int e = 0; e < ne[d]; ++e)
      for (int i = 0; i < nodes[d]; ++i)
        params[d].push_back(brk[e] + (brk[e + 1] - brk[e]) * static_cast<double>(i) / p.degrees[d]);
  }
  const spline::GridEvaluation ev = spline::evaluate_grid(p, params, 1);
  std::vector<double> q(static_cast<std::size_t>(ne[0]) * ne[1] * ne[2], std::numeric_limits<double>::infinity());
  const long nu = static_cast<long>(params[0].size()), nv = static_cast<long>(params[1].size());
  for (long k = 0; k < static_cast<long>(params[2].size()); ++k)
    for (long j = 0; j < nv; ++j)
      for (long i = 0; i < nu; ++i) {
        const long at = i + nu * (j + nv * k);
        double& m = q[static_cast<std::size_t>(i / nodes[0] + ne[0] * (j / nodes[1] + ne[1] * (k / nodes[2])))];
        m = std::min(m, spline::scaled_jacobian(spline::grid_jacobian(ev, at)));
      }
  return q;
}

void write_grid(std::ostream& out, const Grid& g, const VtuOptions& options) {
  const bool solution = !g.von_mises.empty();
  const std::vector<uint8_t> types(g.offsets.size(), 79);  // VTK_BEZIER_HEXAHEDRON
  vtu_header(out, g.weights.size(), g.offsets.size());
  ArrayWriter w(out, options.binary);
  out << "   <PointData RationalWeights=\"RationalWeights\">\n";
  w.array("Float64", "RationalWeights", 1, g.weights, "    ");
  w.array("Int32", "material", 1, g.point_material, "    ");
  w.array("Int32", "patch", 1, g.point_patch, "    ");
  if (solution) {
    w.array("Float64", "displacement", 3, g.displacement, "    ");
    w.array("Float64", "von_mises", 1, g.von_mises, "    ");
  }
  out << "   </PointData>\n";
  out << "   <CellData HigherOrderDegrees=\"HigherOrderDegrees\">\n";
  w.array("Int32", "HigherOrderDegrees", 3, g.degrees, "    ");
  w.array("Int32", "material", 1, g.material, "    ");
  w.array("Int32", "patch", 1, g.patch, "    ");
  w.array("Int32", "element", 3, g.element, "    ");
  w.array("Float64", "min_scaled_jacobian", 1, g.min_scaled_jacobian, "    ");
  if (!options.certified_lower_bound.empty())
    w.array("Float64", "certified_det_lower_bound", 1, options.certified_lower_bound, "    ");
  vtu_points_cells_and_end(out, w, g.points, g.connectivity, g.offsets, types);
}

}  // namespace igaprep::exporter::detail
