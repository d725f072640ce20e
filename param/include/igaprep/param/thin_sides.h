#pragma once
// The two sides of a thin solid (a plate, a blade, a curved wing), as a field
// on T1 whose zero set runs along the solid's rim: a candidate for the cut
// loops that makes M0 the solid's midsurface, across its thin direction.
//
// Each face is paired with the face its inward ray meets first when that face
// faces back (a plate pair); a pair wants opposite signs, neighbouring faces
// want equal signs (weakly across sharp edges), and a weak pull towards the
// sign of n . U (U the surface's smallest principal axis) breaks the symmetry
// between parts the pairs do not tie together (two blades joined by a thick
// hub). The minimiser of that quadratic energy is one sparse solve. Smaller
// pieces of either sign are then given to the other side, so that each side is
// one connected region. Method notes: docs/midsurface.md, "Thin sides".
#include <Eigen/Core>

#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::param {

struct ThinSidesOptions {
  double sharpness = 0.3;      // neighbour weight exp(-(1 - cos(angle between normals)) / sharpness)
  double thin_factor = 2.0;    // plate pairs farther apart than this times the median thickness are not used
  double pull = 1e-4;          // weight of the n . U term relative to the pairs and neighbours
};

struct ThinSides {
  Eigen::VectorXd face_value;    // #F, signed; its sign is the side
  Eigen::VectorXd vertex_value;  // #V, area-weighted mean of the incident faces' values
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  double median_thickness = 0.0;  // of the plate pairs
  int plate_pairs = 0;            // pairs used
  int flipped_pieces = 0;         // pieces given to the other side
};

// Input: T1, closed and oriented outward. Throws bad_input when no face has a
// facing opposite face (nothing thin to split).
ThinSides thin_sides(const mesh::TriMesh& T1, const ThinSidesOptions& options = {});

}  // namespace igaprep::param
