#pragma once
// G+Smo XML (gsFileData / gsXml<gsMultiPatch>): one TensorBSpline3 or
// TensorNurbs3 <Geometry> per patch (id = patch index; coefficients
// Cartesian, u fastest; NURBS weights inside TensorNurbsBasis3) and a
// <MultiPatch parDim="3"> with <patches type="id_range">, <interfaces> (10
// integers per interface: p1 s1 p2 s2, direction map, orientation; one
// <interfaces name="label"> group per input surface) and one
// <boundary name="label"> group per boundary label, the names G+Smo's
// <boundaryConditions><bc name="..."/> refer to. Numbers are written with 17
// significant digits, so they read back exactly.
#include <ostream>
#include <string>

#include "igaprep/spline/multipatch.h"

namespace igaprep::exporter {

// Inputs: model. Output: the XML text on `out`.
void write_gismo_xml(const spline::MultiPatch& model, std::ostream& out);
// Same, to a file written atomically.
void write_gismo_xml(const spline::MultiPatch& model, const std::string& path);

}  // namespace igaprep::exporter
