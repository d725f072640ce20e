#pragma once
// The LS-DYNA keyword deck of any model form (docs/export-formats.md): one
// part per material, its BEXT file included, a node set per label and part.
#include <ostream>
#include <string>
#include <vector>

#include "igaprep/spline/multipatch.h"

namespace igaprep::exporter::detail {

// The part's BEXT node ids (1-based, ascending) on the sides labelled `label`.
struct DeckNodeSet {
  std::string label;
  int pid = 1;
  std::vector<long long> nodes;
};

// part_files[m]: the BEXT file of material m (part m + 1), relative to the
// deck. Node sets without nodes are left out.
void write_deck(const std::string& heading, const std::vector<spline::Material>& materials,
                const std::vector<std::string>& part_files, const std::vector<DeckNodeSet>& sets, std::ostream& out);

}  // namespace igaprep::exporter::detail
