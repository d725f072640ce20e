#include <algorithm>
#include <string>

#include "igaprep/core/error.h"
#include "igaprep/spline/evaluate.h"
#include "igaprep/spline/knot_vector.h"
#include "igaprep/spline/multipatch_topology.h"
#include "igaprep/spline/tspline_model.h"
#include "tspline_common.h"

namespace igaprep::spline {

namespace {

TMesh tensor_mesh(const Patch& p, int index, const std::vector<int>& split_directions) {
  std::array<int, 3> elements{};
  for (std::size_t d = 0; d < 3; ++d) {
    const std::vector<double>& U = p.knots[d];
    const int deg = p.degrees[d];
    const std::vector<double> breaks = unique_knots(U);
    for (std::size_t k = 1; k + 1 < breaks.size(); ++k)
      if (knot_multiplicity(U, breaks[k]) > 1)
        throw bad_input("T-spline: patch " + std::to_string(index) + " has an interior knot " + std::to_string(breaks[k]) +
                        " of multiplicity above 1 in direction " + std::to_string(d) +
                        " (local refinement needs simple interior knots)");
    elements[d] = static_cast<int>(breaks.size()) - 1;
    if (deg % 2 == 0)
      throw bad_input("T-spline: patch " + std::to_string(index) + " has degree " + std::to_string(deg) +
                      " in direction " + std::to_string(d) + " (local refinement is defined for odd degrees)");
  }
  return TMesh(elements, p.degrees, split_directions);
}

// B's face rectangles and A's mapped into B's tangent coordinates.
struct InterfaceFaces {
  std::vector<detail::FaceRect> a, b;
};

InterfaceFaces interface_faces(const TSplineModel& m, const Interface& itf) {
  const TMesh& A = m.meshes[static_cast<std::size_t>(itf.patch_a)];
  const TMesh& B = m.meshes[static_cast<std::size_t>(itf.patch_b)];
  InterfaceFaces out{detail::face_rects(A, itf.side_a), detail::face_rects(B, itf.side_b)};
  const std::array<int, 2> ta = itf.side_a.tangent_directions(), tb = itf.side_b.tangent_directions();
  for (detail::FaceRect& r : out.a) {
    detail::FaceRect mapped = r;
    for (std::size_t k = 0; k < 2; ++k) {
      const int db = itf.dirmap[static_cast<std::size_t>(ta[k])];
      const std::size_t kb = db == tb[0] ? 0 : 1;
      if (itf.orient[static_cast<std::size_t>(ta[k])]) {
        mapped.lo[kb] = r.lo[k];
        mapped.hi[kb] = r.hi[k];
      } else {
        mapped.lo[kb] = B.extent(db) - r.hi[k];
        mapped.hi[kb] = B.extent(db) - r.lo[k];
      }
    }
    r = mapped;
  }
  return out;
}

double area(const detail::FaceRect& r) {
  return static_cast<double>(r.hi[0] - r.lo[0]) * static_cast<double>(r.hi[1] - r.lo[1]);
}

// Splits one box of the coarser side where the two meshes of an interface
// differ; false when they are the same.
bool mirror_once(TSplineModel& m, const Interface& itf) {
  const InterfaceFaces f = interface_faces(m, itf);
  for (const detail::FaceRect& ra : f.a)
    for (const detail::FaceRect& rb : f.b) {
      const bool meet = ra.lo[0] < rb.hi[0] && rb.lo[0] < ra.hi[0] && ra.lo[1] < rb.hi[1] && rb.lo[1] < ra.hi[1];
      if (!meet || (ra.lo == rb.lo && ra.hi == rb.hi)) continue;
      if (area(ra) >= area(rb)) m.meshes[static_cast<std::size_t>(itf.patch_a)].refine(ra.box);
      if (area(rb) >= area(ra)) m.meshes[static_cast<std::size_t>(itf.patch_b)].refine(rb.box);
      return true;
    }
  return false;
}

void mirror_interfaces(TSplineModel& m) {
  for (bool changed = true; changed;) {
    changed = false;
    for (const Interface& itf : m.base.interfaces)
      while (mirror_once(m, itf)) changed = true;
  }
}

// The point of a box's parameter midpoint; breaks: the patch's distinct knots per direction.
Eigen::Vector3d box_centre(const Patch& p, const std::array<std::vector<double>, 3>& breaks, const TBox& b) {
  Eigen::Vector3d u;
  for (std::size_t d = 0; d < 3; ++d)
    u[static_cast<Eigen::Index>(d)] = 0.5 * (detail::index_to_parameter(breaks[d], b.lo[d]) + detail::index_to_parameter(breaks[d], b.hi[d]));
  return evaluate_point(p, u);
}

}  // namespace

TSplineModel tspline_model(const MultiPatch& mp, const std::vector<int>& split_directions) {
  validate_multipatch(mp);
  TSplineModel out;
  out.base = mp;
  for (std::size_t p = 0; p < mp.patches.size(); ++p) out.meshes.push_back(tensor_mesh(mp.patches[p], static_cast<int>(p), split_directions));
  return out;
}

void refine_boxes(TSplineModel& model, const std::vector<std::pair<int, int>>& boxes) {
  for (const auto& [p, b] : boxes) {
    if (p < 0 || p >= static_cast<int>(model.meshes.size()) || b < 0 ||
        b >= static_cast<int>(model.meshes[static_cast<std::size_t>(p)].boxes().size()))
      throw bad_input("T-spline refinement: no box " + std::to_string(b) + " in patch " + std::to_string(p));
  }
  for (const auto& [p, b] : boxes) model.meshes[static_cast<std::size_t>(p)].refine(b);
  mirror_interfaces(model);
}

int refine_in_region(TSplineModel& model, const Eigen::AlignedBox3d& region, int levels) {
  if (levels < 0 || levels > 6) throw bad_input("T-spline refinement: levels must lie in 0..6, got " + std::to_string(levels));
  const long before = tmesh_box_count(model);
  for (std::size_t p = 0; p < model.meshes.size(); ++p) {
    TMesh& mesh = model.meshes[p];
    const Patch& patch = model.base.patches[p];
    const std::array<std::vector<double>, 3> breaks{{unique_knots(patch.knots[0]), unique_knots(patch.knots[1]), unique_knots(patch.knots[2])}};
    for (bool changed = true; changed;) {
      changed = false;
      for (std::size_t b = 0; b < mesh.boxes().size(); ++b) {
        const TBox& q = mesh.boxes()[b];
        if (q.level >= levels * mesh.split_direction_count() || !region.contains(box_centre(patch, breaks, q))) continue;
        mesh.refine(static_cast<int>(b));
        changed = true;
      }
    }
  }
  mirror_interfaces(model);
  return static_cast<int>(tmesh_box_count(model) - before);
}

long tmesh_box_count(const TSplineModel& model) {
  long n = 0;
  for (const TMesh& m : model.meshes) n += static_cast<long>(m.boxes().size());
  return n;
}

}  // namespace igaprep::spline
