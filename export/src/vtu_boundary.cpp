#include "igaprep/export/vtu_boundary.h"

#include <cstdint>
#include <vector>

#include "igaprep/spline/bezier_extraction.h"
#include "model_checks.h"
#include "vtu_arrays.h"

namespace igaprep::exporter {

int vtk_quad_point_index(int i, int j, const std::array<int, 2>& order) {
  const bool ibdy = (i == 0 || i == order[0]);
  const bool jbdy = (j == 0 || j == order[1]);
  if (ibdy && jbdy) return i ? (j ? 2 : 1) : (j ? 3 : 0);  // corner
  const int offset = 4;
  if (!ibdy && jbdy) return (i - 1) + (j ? order[0] - 1 + order[1] - 1 : 0) + offset;  // edge along i
  if (ibdy && !jbdy) return (j - 1) + (i ? order[0] - 1 : 2 * (order[0] - 1) + order[1] - 1) + offset;
  return offset + 2 * (order[0] - 1 + order[1] - 1) + (i - 1) + (order[0] - 1) * (j - 1);  // face
}

namespace {

struct Faces {
  std::vector<double> points, weights;  // 3 and 1 per point
  std::vector<int64_t> connectivity, offsets;
  std::vector<int32_t> degrees, label, patch, side, point_label;
};

// The element's Bernstein points on one of its faces as a Bezier quad: the
// face's two directions in increasing order, the normal index fixed at 0 or p.
void add_face(const spline::Patch& p, const spline::BezierElement& be, const spline::BoundarySide& b, Faces& f) {
  const int n = b.side.direction(), a = n == 0 ? 1 : 0, c = n == 2 ? 1 : 2;
  const std::array<int, 2> deg{p.degrees[a], p.degrees[c]};
  const int fixed = b.side.parameter() ? p.degrees[n] : 0;
  const int64_t base = static_cast<int64_t>(f.weights.size());
  const int count = (deg[0] + 1) * (deg[1] + 1);
  f.points.resize(f.points.size() + 3 * static_cast<std::size_t>(count));
  f.weights.resize(f.weights.size() + static_cast<std::size_t>(count));
  for (int j = 0; j <= deg[1]; ++j)
    for (int i = 0; i <= deg[0]; ++i) {
      std::array<int, 3> ijk{};
      ijk[static_cast<std::size_t>(n)] = fixed;
      ijk[static_cast<std::size_t>(a)] = i;
      ijk[static_cast<std::size_t>(c)] = j;
      const Eigen::Index local = ijk[0] + (p.degrees[0] + 1) * (ijk[1] + (p.degrees[1] + 1) * ijk[2]);
      const auto at = static_cast<std::size_t>(base + vtk_quad_point_index(i, j, deg));
      for (int k = 0; k < 3; ++k) f.points[3 * at + static_cast<std::size_t>(k)] = be.points(local, k);
      f.weights[at] = p.rational() ? be.weights[local] : 1.0;
    }
  for (int q = 0; q < count; ++q) f.connectivity.push_back(base + q);
  f.offsets.push_back(static_cast<int64_t>(f.connectivity.size()));
  f.degrees.insert(f.degrees.end(), {deg[0], deg[1], 0});
  f.label.push_back(b.label);
  f.patch.push_back(b.patch);
  f.side.push_back(b.side.index());
  f.point_label.resize(f.weights.size(), b.label);
}

// Every element face on every labelled side.
Faces boundary_faces(const spline::MultiPatch& model) {
  Faces f;
  for (const spline::BoundarySide& b : model.boundaries) {
    const spline::Patch& p = model.patches[static_cast<std::size_t>(b.patch)];
    const spline::PatchExtraction ex = spline::bezier_extraction(p);
    const int n = b.side.direction();
    std::array<int, 3> lo{0, 0, 0}, hi{ex.element_count(0), ex.element_count(1), ex.element_count(2)};
    lo[static_cast<std::size_t>(n)] = b.side.parameter() ? hi[static_cast<std::size_t>(n)] - 1 : 0;
    hi[static_cast<std::size_t>(n)] = lo[static_cast<std::size_t>(n)] + 1;
    for (int ew = lo[2]; ew < hi[2]; ++ew)
      for (int ev = lo[1]; ev < hi[1]; ++ev)
        for (int eu = lo[0]; eu < hi[0]; ++eu) add_face(p, spline::bernstein_control_points(p, ex, eu, ev, ew), b, f);
  }
  return f;
}

}  // namespace

void write_vtu_boundary(const spline::MultiPatch& model, std::ostream& out, const VtuOptions& options) {
  detail::check_model_for_writing(model, "VTU boundary");
  const Faces f = boundary_faces(model);
  const std::vector<uint8_t> types(f.offsets.size(), 77);  // VTK_BEZIER_QUADRILATERAL
  detail::vtu_header(out, f.weights.size(), f.offsets.size());
  detail::ArrayWriter w(out, options.binary);
  out << "   <PointData RationalWeights=\"RationalWeights\">\n";
  w.array("Float64", "RationalWeights", 1, f.weights, "    ");
  w.array("Int32", "label", 1, f.point_label, "    ");
  out << "   </PointData>\n";
  out << "   <CellData HigherOrderDegrees=\"HigherOrderDegrees\">\n";
  w.array("Int32", "HigherOrderDegrees", 3, f.degrees, "    ");
  w.array("Int32", "label", 1, f.label, "    ");
  w.array("Int32", "patch", 1, f.patch, "    ");
  w.array("Int32", "side", 1, f.side, "    ");
  detail::vtu_points_cells_and_end(out, w, f.points, f.connectivity, f.offsets, types);
}

}  // namespace igaprep::exporter
