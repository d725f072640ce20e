#include "bext_parts.h"

#include <cstddef>

#include "igaprep/spline/multipatch_topology.h"

namespace igaprep::exporter::detail {

std::vector<BextPart> bext_parts(const spline::MultiPatch& model) {
  const spline::GlobalNumbering numbering = spline::global_numbering(model);
  std::vector<BextPart> parts(model.materials.size());
  for (std::size_t m = 0; m < parts.size(); ++m) {
    parts[m].material = static_cast<int>(m);
    parts[m].pid = static_cast<int>(m) + 1;
  }
  std::vector<std::vector<long long>> node_of_global(parts.size(),
                                                     std::vector<long long>(static_cast<std::size_t>(numbering.count), 0));
  for (std::size_t p = 0; p < model.patches.size(); ++p) {
    const auto m = static_cast<std::size_t>(model.patches[p].material);
    BextPart& part = parts[m];
    part.patches.push_back(static_cast<int>(p));
    std::vector<long long> nodes;
    for (std::size_t l = 0; l < numbering.global[p].size(); ++l) {
      const int g = numbering.global[p][l];
      long long& id = node_of_global[m][static_cast<std::size_t>(g)];
      if (id == 0) {
        part.node_source.emplace_back(static_cast<int>(p), static_cast<int>(l));
        id = static_cast<long long>(part.node_source.size());
      }
      nodes.push_back(id);
    }
    part.node_of.push_back(std::move(nodes));
  }
  return parts;
}

}  // namespace igaprep::exporter::detail
