#pragma once
// Files of a T-NURCC surface (docs/tnurcc.md):
//  - the cage as OBJ: "v x y z", quad faces "f a b c d" (1-based, counter-
//    clockwise seen from outside), creases as OpenSubdiv's OBJ tags
//    "t crease 2/1/0 a b sharpness" (0-based vertex indices, 10 = infinitely
//    sharp);
//  - its knot intervals as JSON: {"format": "igaprep-tnurcc-intervals",
//    "version": 1, "edges": [[a, b, interval], ...]} (0-based);
//  - its limit surface as a VTU of quadrilaterals, n x n per cage face,
//    with point data "Normals" (unit, outward) and "MeanCurvature"
//    (positive where the surface bulges outward), cell data "face".
#include <istream>
#include <ostream>

#include "igaprep/spline/tnurcc_cage.h"
#include "igaprep/spline/tnurcc_limit.h"

namespace igaprep::exporter {

void write_cage_obj(const spline::Cage& cage, std::ostream& out);

// Reads what write_cage_obj writes (and OBJ quad meshes in general: "v",
// "f" with "a/b/c" indices, "t crease"); every interval 1. Throws bad_input
// naming the line for anything it cannot read.
spline::Cage read_cage_obj(std::istream& in);

void write_cage_intervals(const spline::Cage& cage, std::ostream& out);

// Inputs: the cage (equal intervals), quads per face and direction (>= 1).
void write_limit_vtu(const spline::Cage& cage, int per_face, std::ostream& out,
                     const spline::LimitOptions& options = {});

}  // namespace igaprep::exporter
