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
  return out;
}

}  // namespace igaprep::param
