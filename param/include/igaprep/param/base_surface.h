#pragma once
// The base surface M the volume decomposition is built on (section 4.4 of
// the seed paper, as this project makes it): M0trim's (u, v) replaced by the
// sliding one where that is valid (sliding_uv.h), then M0trim inset in that
// domain (inset_base.h). The one place that makes M: the run and the tests
// use it.
#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/param/inset_base.h"
#include "igaprep/param/polycube_2d.h"
#include "igaprep/param/rim_reach.h"
#include "igaprep/param/sliding_uv.h"

namespace igaprep::param {

// The case's choices for M (section "decomposition" of a case file).
struct BaseSurfaceOptions {
  double inset = 0.3;  // d = inset x half the narrowest band of M0trim's domain, in (0, 1)
  // Where the solid is thin at M0trim's rim, d is capped so that M's edge
  // lies at most this many half-thicknesses from the rim (rim_reach.h; 0: off).
  double rim_reach = 2.0;
  // Rounds of Taubin smoothing of M along its normals (halved while M
  // intersects itself; 20 made M intersect itself on torus3).
  int smoothing = 5;
  bool sliding_uv = true;  // cut along the iso-lines of sliding_uv.h (else the midsurface's (u, v))
  // The layout's grid intervals longer than this times the longest one
  // across are cut into equal parts (0: the holes' grid as it is; the
  // built-in models' intervals are within 1.6 of each other).
  double max_aspect = 2.0;
};

struct BaseSurface {
  InsetBase m;             // M with its (u, v) and domain
  Polycube2D polycube;     // the (u, v) M was cut along (the sliding one when used)
  SlidingUv sliding;       // empty unless options.sliding_uv
  bool sliding_used = false;
  RimReach rim;                // the cap on d where the solid is thin at the rim (rim.cap: the d used)
  double inset = 0.0;          // the inset fraction used (options.inset, or less where the rim capped it)
};

// Inputs: M0trim and its 2D polycube (the midsurface's result), options,
// the surface M0trim's boundary lies on (Tn; null: no cap by the rim).
// Output: M. Throws like inset_base_surface.
BaseSurface base_surface(const mesh::TriMesh& m0trim, const Polycube2D& polycube, const BaseSurfaceOptions& options,
                         const SurfaceProjector* rim = nullptr);

}  // namespace igaprep::param
