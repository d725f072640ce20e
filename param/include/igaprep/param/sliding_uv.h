#pragma once
// A (u, v) of a sheet onto its rectilinear domain that is closer to
// orthogonal near the domain's corners, for cutting the base surface.
//
// The midsurface's (u, v) fixes each side's vertices by 3D arc length. Where
// the sheet's boundary is smooth and the domain has a corner, that map is far
// from conformal, and the base surface's sides cut along u = d and v = d meet
// far from 90 degrees in 3D (the shell blocks at such a corner open to 180
// degrees on their way to T1). If instead a side's vertices slide along it
// (u harmonic with u fixed on the u-iso sides and a natural boundary on the
// v-iso sides, v the other way round), u and v near a corner are, to leading
// order, the real and imaginary parts of one square-root-like conformal map,
// whose iso-lines cross at right angles. At the inset corners the pipeline
// uses (about one triangle of M0trim from the domain's corner, where the
// leading order does not dominate yet) the gain is partial: mean |90 - angle|
// 34 -> 18 degrees on sphere2, 47 -> 35 on ring2, 31 -> 16 on torus3
// (tests/param/test_volume_smoothing.cpp).
//
// The sliding solution need not keep a side's vertices in order (torus3's,
// sphere2's), so its boundary positions are blended with the arc-length
// ones, per side as little as keeps them strictly in order; the (u, v) is
// then the harmonic map with that boundary (equal to the sliding solution
// where no blending was needed), untangled like the midsurface's.
#include <string>

#include <Eigen/Core>

#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/param/polycube_2d.h"

namespace igaprep::param {

struct SlidingUv {
  Eigen::MatrixXd uv;          // #V x 2
  bool valid = false;          // every triangle positively oriented
  double min_jacobian = 0.0;   // uv_jacobians, smallest
  double min_sliding_share = 1.0;  // smallest blend weight of the sliding positions over the sides (1: pure)
  std::string reason;          // why not valid
};

// Inputs: the sheet and its 2D polycube (domain, boundary segments; the same
// vertices as polycube.uv). Output: the (u, v), valid or with the reason it
// is not (the caller then keeps polycube.uv).
SlidingUv sliding_uv(const mesh::TriMesh& sheet, const Polycube2D& polycube);

}  // namespace igaprep::param
