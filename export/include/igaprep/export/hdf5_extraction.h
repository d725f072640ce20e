#pragma once
// The Bezier-extraction model file (format "igaprep-bezier-extraction",
// version 1; docs/hdf5-format.md documents it field by field, so that
// another program can read it without igaprep): the form T-spline models
// take (spline/extraction_model.h).
#include <string>

#include "igaprep/spline/extraction_model.h"

namespace igaprep::exporter {

// Written atomically. Throws bad_input for an element whose operator's
// shape does not match its functions and degrees, or a function id, face
// or material out of range.
void write_hdf5_extraction(const spline::ExtractionModel& model, const std::string& path);

}  // namespace igaprep::exporter
