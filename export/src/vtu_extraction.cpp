// VTU of a model in Bezier-extraction form: each element's Bernstein points
// (spline::bernstein_element) as a Bezier hexahedron; the arrays and their
// layout are those of the multipatch VTU (vtu_grid.h, vtu_arrays.h).
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
    detail::add_cell(g, be, detail::vtk_hex_order(el.degrees), el.degrees, el.material, el.patch, el.index,
                     detail::element_min_scaled_jacobians(bezier_patch(be, el.degrees)).front());
  }
  detail::share_coincident_points(g);
  return g;
}

}  // namespace

void write_vtu_bezier(const spline::ExtractionModel& model, std::ostream& out) {
  detail::write_grid(out, extraction_grid(model), VtuOptions{});
}

void write_vtu_bezier(const spline::ExtractionModel& model, const std::string& path) {
  write_file_atomically(path, [&](std::ostream& out) { write_vtu_bezier(model, out); }, true);
}

}  // namespace igaprep::exporter
