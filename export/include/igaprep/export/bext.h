#pragma once
// LS-DYNA isogeometric solids: one BEXT 2.0 ASCII Bezier-extraction file per
// material (one part each, as *IGA_INCLUDE_BEZIER takes one part per file)
// and a keyword deck that includes them with their parts, sections, elastic
// materials and a node set per boundary label. docs/export-formats.md gives
// the layout, the source of every field, and what could not be checked
// against LS-DYNA itself.
#include <ostream>
#include <string>
#include <vector>

#include "igaprep/spline/extraction_model.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::exporter {

// The deck BASENAME.k, then BASENAME_part<pid>.bext for pid = 1..materials.
std::vector<std::string> bext_paths(const std::string& basename, int materials);

// The BEXT file of one material's patches: its control points (numbered
// 1..n in the order its patches first use them), one element block per
// patch, the distinct rows of the elements' extraction operators as dense
// coefficient vectors shared by the elements that use them.
void write_bext_part(const spline::MultiPatch& model, int material, std::ostream& out);

// The keyword deck: *PART, *SECTION_IGA_SOLID, *MAT_ELASTIC and
// *IGA_INCLUDE_BEZIER per material (part_files[m] the file name the deck
// refers to, relative to the deck), *SET_NODE_LIST per boundary label and part.
void write_lsdyna_deck(const spline::MultiPatch& model, const std::vector<std::string>& part_files, std::ostream& out);

// The same for a model in Bezier-extraction form (a T-spline): a part is a
// material's elements, its nodes the functions they use; elements are
// grouped into element blocks by degrees and number of functions (a block
// holds one node count); node sets from the labelled boundary faces.
void write_bext_part(const spline::ExtractionModel& model, int material, std::ostream& out);
void write_lsdyna_deck(const spline::ExtractionModel& model, const std::vector<std::string>& part_files, std::ostream& out);

// export_model (export_model.h) writes all of bext_paths at once.

}  // namespace igaprep::exporter
