#pragma once
// A model split into LS-DYNA parts, one per material (one BEXT file each):
// the part's patches and its control points numbered 1..n in the order its
// patches first use them. Shared by the BEXT writer and the keyword deck.
#include <utility>
#include <vector>

#include "igaprep/spline/multipatch.h"

namespace igaprep::exporter::detail {

struct BextPart {
  int material = 0;
  int pid = 0;                    // LS-DYNA part id: material + 1
  std::vector<int> patches;       // in model order
  std::vector<std::pair<int, int>> node_source;  // part node (0-based) -> (patch, local control point) first using it
  // Per patch of `patches`, per local control point: the part node, 1-based.
  std::vector<std::vector<long long>> node_of;
};

// One part per material of the model, in material order (a material
// without patches gives a part without patches).
std::vector<BextPart> bext_parts(const spline::MultiPatch& model);

}  // namespace igaprep::exporter::detail
