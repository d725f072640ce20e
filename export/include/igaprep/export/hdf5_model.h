#pragma once
// igaprep's own model file: HDF5, "HDF5 model format, version 1" of
// ARCHITECTURE.md (user documentation: docs/hdf5-format.md). The writer and
// the reader round-trip every number bit for bit, including weights, solve
// results (per-patch displacement, strain energy, max displacement) and
// provenance. The same model always gives a byte-identical file.
#include <string>

#include "igaprep/core/atomic_file.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::exporter {

// Inputs: model (patches with valid knot vectors and control points), path.
// Output: the file at `path`, written atomically (temporary name, then rename).
// Throws bad_input when the model is inconsistent (names the patch) or the
// file cannot be written.
void write_hdf5_model(const spline::MultiPatch& model, const std::string& path);
// The same into `target`'s temporary file, left for the caller to commit.
void write_hdf5_model(const spline::MultiPatch& model, AtomicPath& target);

// Inputs: path of a file written by write_hdf5_model (or any writer following
// the format). Output: the model. Checks the format name and version and the
// shape, type and values of every dataset; a bad file gives bad_input naming
// the file and the dataset at fault. HDF5's own error printing is suppressed.
spline::MultiPatch read_hdf5_model(const std::string& path);

}  // namespace igaprep::exporter
