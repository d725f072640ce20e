#pragma once
// Cuts along edge paths made smooth: the loops of a cut that follow T1's
// edges (waypoint paths, tunnel loops) zigzag along the triangles, which can
// make M0 non-manifold along a loop on a coarse tet mesh.
#include <string>

#include "igaprep/param/cut_loops.h"

namespace igaprep::param::detail {

// The cut along the zero set of the vertices' sides (+1 / -1, 0 on the
// loops) smoothed by `rounds` of neighbour averaging, named `smoothed_source`,
// when it is valid with as many loops; `edges` itself otherwise.
CutLoops smoothed_cut(CutLoops edges, const std::string& name, const std::string& smoothed_source, int rounds = 3);

}  // namespace igaprep::param::detail
