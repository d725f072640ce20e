// VTU of a model in Bezier-extraction form: each element's Bernstein points
// (spline::bernstein_element) as a Bezier hexahedron; the arrays and their
// layout are those of the multipatch VTU (vtu_grid.h, vtu_arrays.h).
#include <cstdint>

#include "igaprep/core/atomic_file.h"
#include "igaprep/core/error.h"
#include "igaprep/export/vtu_bezier.h"
#include "vtu_grid.h"

namespace igaprep::exporter {

namespace {

// The element as a one-element patch on [0, 1]^3, for the scaled Jacobian.
spline::Patch bezier_patch(const spline::BezierElement& be, const std::array<int, 3>& degrees) {
  spline::Patch p;
  p.degrees = degrees;
  for (int d = 0; d < 3; ++d) {
    p.knots[static_cast<std::size_t>(d)].assign(static_cast<std::size_t>(degrees[static_cast<std::size_t>(d)] + 1), 0.0);
    p.knots[static_cast<std::size_t>(d)].resize(2 * static_cast<std::size_t>(degrees[static_cast<std::size_t>(d)] + 1), 1.0);
  }
  p.control_points = be.points;
  p.weights = be.weights;
  return p;
}

detail::Grid extraction_grid(const spline::ExtractionModel& m) {
  detail::Grid g;
  for (int e = 0; e < static_cast<int>(m.elements.size()); ++e) {
    const spline::ExtractionElement& el = m.elements[static_cast<std::size_t>(e)];
    for (int d = 0; d < 3; ++d)
      if (el.degrees[static_cast<std::size_t>(d)] < 1)
        throw bad_input("VTU Bezier: element " + std::to_string(e) + " has degree 0 (VTK Bezier cells need degree >= 1)");
    const spline::BezierElement be = spline::bernstein_element(m, e);
    const std::vector<int> vtk_of_local = detail::vtk_hex_order(el.degrees);
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
    g.degrees.insert(g.degrees.end(), el.degrees.begin(), el.degrees.end());
    g.material.push_back(el.material);
    g.patch.push_back(el.patch);
    g.element.insert(g.element.end(), el.index.begin(), el.index.end());
    const std::array<std::array<double, 2>, 3> unit{{{{0.0, 1.0}}, {{0.0, 1.0}}, {{0.0, 1.0}}}};
    g.min_scaled_jacobian.push_back(detail::element_min_scaled_jacobian(bezier_patch(be, el.degrees), unit));
    g.point_material.resize(g.weights.size(), el.material);
    g.point_patch.resize(g.weights.size(), el.patch);
  }
  detail::share_coincident_points(g);
  return g;
}

}  // namespace

void write_vtu_bezier(const spline::ExtractionModel& model, const std::string& path) {
  const detail::Grid g = extraction_grid(model);
  write_file_atomically(path, [&](std::ostream& out) { detail::write_grid(out, g, VtuOptions{}); }, true);
}

}  // namespace igaprep::exporter
