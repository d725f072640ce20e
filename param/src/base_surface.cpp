#include "igaprep/param/base_surface.h"

namespace igaprep::param {

BaseSurface base_surface(const mesh::TriMesh& m0trim, const Polycube2D& polycube, const BaseSurfaceOptions& options) {
  BaseSurface out;
  out.polycube = polycube;
  if (options.sliding_uv) out.sliding = sliding_uv(m0trim, polycube);
  if (out.sliding.valid) {
    out.polycube.uv = out.sliding.uv;
    out.sliding_used = true;
  }
  out.m = inset_base_surface(m0trim, out.polycube, options.inset, options.smoothing);
  // The sliding (u, v) is checked on M0trim; cut along it, M can still get a
  // folded triangle next to a corner: then M is cut along the midsurface's.
  if (out.sliding_used && !(uv_jacobians(out.m.mesh, out.m.uv).minCoeff() > 0.0)) {
    out.sliding.valid = false;
    out.sliding.reason = "M cut along it has a folded triangle";
    out.sliding_used = false;
    out.polycube = polycube;
    out.m = inset_base_surface(m0trim, out.polycube, options.inset, options.smoothing);
  }
  return out;
}

}  // namespace igaprep::param
