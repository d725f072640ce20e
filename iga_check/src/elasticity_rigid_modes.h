#pragma once
// Internal to the elasticity solver: constraints that leave a rigid-body
// motion free make the stiffness singular; found before assembly.
#include <vector>

#include "igaprep/spline/multipatch.h"
#include "igaprep/spline/multipatch_topology.h"

namespace igaprep::iga_check::detail {

// Six rigid-body modes against the constrained components (constrained[3 g + i]
// for component i of global control point g), per connected part of the
// model: a combination of modes that vanishes on every constrained component
// of a part is a free motion. Throws bad_input naming the part's patches, a
// free motion and the labels of the part's boundaries.
void check_rigid_modes(const spline::MultiPatch& mp, const spline::GlobalNumbering& num,
                       const std::vector<unsigned char>& constrained);

}  // namespace igaprep::iga_check::detail
