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

// Whether the file is an HDF5 file whose root attribute format says
// igaprep-bezier-extraction (false for anything else, unreadable included).
bool is_hdf5_extraction(const std::string& path);

// Reads such a file, checking every count, offset, index and shape; a
// defect is bad_input naming the file and the dataset.
spline::ExtractionModel read_hdf5_extraction(const std::string& path);

}  // namespace igaprep::exporter
