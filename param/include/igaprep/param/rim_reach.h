#pragma once
// How far M's edge may be inset where the solid is thin at M0trim's rim.
//
// The crest's streamlines leave M's edge for the rim of the solid through
// the gap between them. Where that gap is much longer than the solid is
// thick (a plate with a flat rim, inset by a share of its width), w decays
// across the gap like exp(-pi length / thickness) and the streamlines reach
// almost none of the rim: the blocks leave it uncovered. Where the rim is
// round the gap is about as long as it is thick and any inset is fine. So
// the inset is capped where, at M0trim's points within it, the distance to
// the rim exceeds `reach` times the distance to the surface the rim lies on.
#include <vector>

#include <Eigen/Core>

#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::param {

class SurfaceProjector;

struct RimReach {
  double cap = 0.0;          // the largest inset d allowed, in (u, v) units (= nominal: no cap)
  int thin = 0;              // vertices within the nominal inset where the solid is thinner than the reach allows
  int considered = 0;        // vertices within the nominal inset
  double half_thickness = 0; // median distance to the surface over the thin vertices (3D)
};

// Inputs: M0trim (3D) with its (u, v) and boundary loops (vertex lists), the
// surface its boundary lies on (Tn, T1 for one material), the nominal inset
// d in (u, v) units, reach > 0. Each vertex p at (u, v) distance delta < d
// from the boundary, 3D distance D from the boundary and r from the surface
// allows the inset delta * reach * r / D when D > reach * r (a flat rim:
// the inset reaches `reach` half-thicknesses); the cap is the first quartile
// of what the considered vertices allow (d where they allow more), so that a
// thin spot alone does not shrink M everywhere.
RimReach rim_reach_cap(const mesh::TriMesh& sheet, const Eigen::MatrixXd& uv, const std::vector<std::vector<int>>& loops,
                       const SurfaceProjector& rim, double nominal, double reach);

}  // namespace igaprep::param
