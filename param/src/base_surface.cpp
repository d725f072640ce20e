#include "igaprep/param/base_surface.h"

#include <algorithm>

namespace igaprep::param {

namespace {

// The least inset fraction a cap may leave: below it M's edge meets the rim
// within a triangle or two of M0trim.
constexpr double kMinCappedInset = 0.02;

}  // namespace

BaseSurface base_surface(const mesh::TriMesh& m0trim, const Polycube2D& polycube, const BaseSurfaceOptions& options,
                         const SurfaceProjector* rim) {
  BaseSurface out;
  out.polycube = polycube;
  if (options.sliding_uv) out.sliding = sliding_uv(m0trim, polycube);
  if (out.sliding.valid) {
    out.polycube.uv = out.sliding.uv;
    out.sliding_used = true;
  }
  out.inset = options.inset;
  const double half_band = 0.5 * narrowest_band(out.polycube.domain);
  out.rim.cap = options.inset * half_band;
  if (rim && options.rim_reach > 0.0) {
    std::vector<std::vector<int>> loops;
    for (const PolycubeLoop& l : out.polycube.loops) loops.push_back(l.vertices);
    out.rim = rim_reach_cap(m0trim, out.polycube.uv, loops, *rim, out.rim.cap, options.rim_reach);
    out.inset = std::clamp(out.rim.cap / half_band, std::min(kMinCappedInset, options.inset), options.inset);
  }
  out.m = inset_base_surface(m0trim, out.polycube, out.inset, options.smoothing);
  // The sliding (u, v) is checked on M0trim; cut along it, M can still get a
  // folded triangle next to a corner: then M is cut along the midsurface's.
  if (out.sliding_used && !(uv_jacobians(out.m.mesh, out.m.uv).minCoeff() > 0.0)) {
    out.sliding.valid = false;
    out.sliding.reason = "M cut along it has a folded triangle";
    out.sliding_used = false;
    out.polycube = polycube;
    out.m = inset_base_surface(m0trim, out.polycube, out.inset, options.smoothing);
  }
  return out;
}

}  // namespace igaprep::param
