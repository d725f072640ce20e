#include "igaprep/param/base_layout.h"

#include <algorithm>

#include "igaprep/core/error.h"

namespace igaprep::param {

namespace {

// The four sides of a box (umin, vmin, umax, vmax) in DomainSide order, each
// from its start to its end corner counter-clockwise, with the normal pointing
// out of the box.
std::array<DomainEdge, 4> box_sides(const Eigen::Vector4d& r) {
  const Eigen::Vector2d c00(r(0), r(1)), c10(r(2), r(1)), c11(r(2), r(3)), c01(r(0), r(3));
  return {{{c00, c10, Eigen::Vector2d(0, -1)},
           {c10, c11, Eigen::Vector2d(1, 0)},
           {c01, c11, Eigen::Vector2d(0, 1)},
           {c00, c01, Eigen::Vector2d(-1, 0)}}};
}

// L's rectangles, domain edges and crest segments from its domain, max_aspect and extra lines.
void cut_domain(BaseLayout& L) {
  L.rectangles = domain_rectangles(L.domain, L.max_aspect, L.extra);
  L.domain_edges.clear();
  L.crests.clear();
  const RectilinearDomain& D = L.domain;

  // The domain's own sides: outward of the outer boundary (the rectangle's
  // sides and its arms'), into each hole.
  for (const DomainSide side : {DomainSide::Bottom, DomainSide::Right, DomainSide::Top, DomainSide::Left}) {
    const std::vector<Eigen::Vector2d> pts = side_walk(D, side);
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
      const Eigen::Vector2d d = (pts[i + 1] - pts[i]).normalized();
      // Each edge from its lower to its upper end, as a box's sides run.
      const bool forward = pts[i].x() + pts[i].y() <= pts[i + 1].x() + pts[i + 1].y();
      L.domain_edges.push_back({forward ? pts[i] : pts[i + 1], forward ? pts[i + 1] : pts[i], Eigen::Vector2d(d.y(), -d.x())});
    }
  }
  for (const auto& h : D.holes)
    for (auto e : box_sides(h)) {
      e.outward = -e.outward;
      L.domain_edges.push_back(e);
    }

  // A rectangle side is on M's boundary when just beyond its middle lies outside the domain.
  const double eps = 1e-6 * std::min(D.width, D.height);
  for (std::size_t r = 0; r < L.rectangles.size(); ++r) {
    const auto sides = box_sides(L.rectangles[r]);
    for (int s = 0; s < 4; ++s) {
      const Eigen::Vector2d probe = 0.5 * (sides[s].a + sides[s].b) + eps * sides[s].outward;
      if (inside_domain(D, probe)) continue;
      L.crests.push_back({static_cast<int>(r), s, sides[s].a, sides[s].b});
    }
  }
  if (L.crests.empty()) throw internal_error("base layout: no rectangle side lies on M's boundary");
}

}  // namespace

BaseLayout base_layout(const InsetBase& base, double max_aspect, const GridLines& extra) {
  BaseLayout L;
  L.sheet = base.mesh;
  L.uv = base.uv;
  L.domain = base.domain;
  L.max_aspect = max_aspect;
  L.extra = extra;
  cut_domain(L);
  return L;
}

BaseLayout with_more_lines(const BaseLayout& L, const GridLines& more) {
  BaseLayout out = L;
  out.extra.u.insert(out.extra.u.end(), more.u.begin(), more.u.end());
  out.extra.v.insert(out.extra.v.end(), more.v.begin(), more.v.end());
  cut_domain(out);
  return out;
}

}  // namespace igaprep::param
