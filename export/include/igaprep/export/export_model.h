#pragma once
// One call that writes a model in several file formats (the `igaprep export`
// command): BASENAME.h5 (igaprep HDF5), .xml (G+Smo), .mesh (MFEM NURBS),
// .vtu (VTK Bezier hexahedra, and _boundary.vtu: the labelled sides as
// Bezier quadrilaterals), .k with _part<N>.bext (an LS-DYNA deck and one
// BEXT 2.0 file per material).
#include <string>
#include <vector>

#include "igaprep/core/progress.h"
#include "igaprep/export/vtu_bezier.h"
#include "igaprep/spline/extraction_model.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::exporter {

enum class Format { Hdf5, Gismo, Mfem, Vtu, Bext };

// "hdf5,gismo,vtu" -> formats in the given order, duplicates dropped.
// Throws bad_input naming an unknown format and listing the known ones.
std::vector<Format> parse_formats(const std::string& comma_separated);

std::string format_name(Format f);       // "hdf5", "gismo", ...
std::string format_extension(Format f);  // ".h5", ".xml", ".mesh", ".vtu", ".k"

// The files a format writes for BASENAME and a model of `materials`
// materials (vtu: two; bext: the deck and one file per material).
std::vector<std::string> format_paths(const std::string& basename, Format f, int materials);

// Writes format_paths() for each format, all or none (each file atomically,
// renamed into place together). Returns the paths written, in order.
// vtu: options for BASENAME.vtu (e.g. the elements' certified bounds).
// progress, if given: task "export", formats done of all, after each.
std::vector<std::string> export_model(const spline::MultiPatch& model, const std::string& basename,
                                      const std::vector<Format>& formats, const VtuOptions& vtu = {},
                                      const ProgressCallback& progress = {});

// The files a format writes for a model in Bezier-extraction form (a
// T-spline): vtu (only BASENAME.vtu: no boundary file) and bext. The other
// formats hold tensor-product patches: bad_input.
std::vector<std::string> extraction_format_paths(const std::string& basename, Format f, int materials);

// Writes extraction_format_paths() for each format, all or none; a format
// this form has not is refused before any file is written.
std::vector<std::string> export_extraction_model(const spline::ExtractionModel& model, const std::string& basename,
                                                 const std::vector<Format>& formats);

}  // namespace igaprep::exporter
