#pragma once
// Private to export/: the consistency every writer needs before it writes a
// model (sizes agree, indices in range, numbers finite). Throws bad_input
// naming `what` (the output file) and the patch, interface or boundary at fault.
#include <string>

#include "igaprep/spline/multipatch.h"

namespace igaprep::exporter::detail {

void check_model_for_writing(const spline::MultiPatch& model, const std::string& what);

// "u", "v" or "w".
inline const char* direction_name(int d) { return d == 0 ? "u" : d == 1 ? "v" : "w"; }

}  // namespace igaprep::exporter::detail
