#pragma once
// The /provenance of a model a run writes (docs/hdf5-format.md): what made
// it, from which case and inputs, and when.
#include <string>

#include "igaprep/iga_check/report.h"
#include "igaprep/pipeline/case.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::pipeline {

// SHA-256 of a file's bytes, as 64 lowercase hex digits. Throws bad_input
// when the file cannot be read.
std::string sha256_of_file(const std::string& path);

// The run's date and time in UTC (ISO 8601): SOURCE_DATE_EPOCH when that is
// set (reproducible outputs), else now.
std::string run_date_utc();

// Fills model.provenance_*: generator (version and git revision), case (the
// case file's text, or the built-in case as JSON), inputs (JSON: per surface
// its label and file with SHA-256, every option's value, the date).
void fill_provenance(const Case& c, spline::MultiPatch& model);

// Sets the report's generator (generator_name()) and date (run_date_utc()).
void stamp_report(iga_check::CheckReport& report);

}  // namespace igaprep::pipeline
