// BEXT part files and the LS-DYNA deck of a model in Bezier-extraction form
// (T-splines). An element block holds one node count, so elements are
// grouped into blocks by degrees and function count (an analysis-suitable
// T-spline has (p+1)(q+1)(r+1) functions on every element, other
// extraction models need not; docs/export-formats.md).
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "bext_file.h"
#include "igaprep/core/error.h"
#include "igaprep/export/bext.h"
#include "lsdyna_deck.h"

namespace igaprep::exporter {

namespace {

// One material's elements and its functions numbered 1..n in the order
// those elements first use them.
struct ExtractionPart {
  std::vector<int> elements;
  std::vector<int> function_of_node;    // node - 1 -> function
  std::vector<long long> node_of;       // function -> node (1-based), 0 outside the part
};

ExtractionPart extraction_part(const spline::ExtractionModel& m, int material) {
  ExtractionPart part;
  part.node_of.assign(static_cast<std::size_t>(m.function_count()), 0);
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    if (m.elements[e].material != material) continue;
    part.elements.push_back(static_cast<int>(e));
    for (const int f : m.elements[e].functions)
      if (part.node_of[static_cast<std::size_t>(f)] == 0) {
        part.function_of_node.push_back(f);
        part.node_of[static_cast<std::size_t>(f)] = static_cast<long long>(part.function_of_node.size());
      }
  }
  return part;
}

void check_material(const spline::ExtractionModel& m, int material, const char* what) {
  if (m.elements.empty()) throw bad_input(std::string(what) + ": the model has no elements");
  if (material < 0 || material >= static_cast<int>(m.materials.size()))
    throw bad_input(std::string(what) + ": no material " + std::to_string(material) + " in a model of " +
                    std::to_string(m.materials.size()));
}

}  // namespace

void write_bext_part(const spline::ExtractionModel& model, int material, std::ostream& out) {
  check_material(model, material, "BEXT");
  const ExtractionPart part = extraction_part(model, material);
  detail::BextFile f;
  f.pid = material + 1;
  f.comment = "part " + std::to_string(f.pid) + ", material '" + model.materials[static_cast<std::size_t>(material)].name +
              "', " + std::to_string(part.elements.size()) +
              " elements of a Bezier-extraction model (element blocks by degrees and functions per element)";
  for (const int fn : part.function_of_node)
    f.nodes.emplace_back(model.control_points(fn, 0), model.control_points(fn, 1), model.control_points(fn, 2),
                         model.weights.size() ? model.weights[fn] : 1.0);
  std::map<std::pair<std::array<int, 3>, std::size_t>, std::size_t> block_of;
  for (const int e : part.elements) {
    const spline::ExtractionElement& el = model.elements[static_cast<std::size_t>(e)];
    const auto key = std::make_pair(el.degrees, el.functions.size());
    auto at = block_of.find(key);
    if (at == block_of.end()) {
      at = block_of.emplace(key, f.blocks.size()).first;
      f.blocks.push_back({el.degrees, detail::dense_block_for(f, el.degrees), {}});
    }
    detail::BextElementBlock& block = f.blocks[at->second];
    std::vector<long long> nodes;
    for (const int fn : el.functions) nodes.push_back(part.node_of[static_cast<std::size_t>(fn)]);
    block.elements.push_back(detail::bext_element(nodes, model.C(e), f.dense[block.dense]));
  }
  detail::write_bext_file(f, out);
}

void write_lsdyna_deck(const spline::ExtractionModel& model, const std::vector<std::string>& part_files, std::ostream& out) {
  check_material(model, 0, "LS-DYNA deck");
  std::vector<ExtractionPart> parts;
  for (int m = 0; m < static_cast<int>(model.materials.size()); ++m) parts.push_back(extraction_part(model, m));
  std::vector<std::vector<std::set<long long>>> nodes(model.labels.size(), std::vector<std::set<long long>>(parts.size()));
  for (const spline::ExtractionBoundaryFace& face : model.boundary_faces) {
    const auto m = static_cast<std::size_t>(model.elements[static_cast<std::size_t>(face.element)].material);
    const std::vector<int>& functions = model.elements[static_cast<std::size_t>(face.element)].functions;
    for (const int r : spline::face_functions(model, face.element, face.side))
      nodes[static_cast<std::size_t>(face.label)][m].insert(parts[m].node_of[static_cast<std::size_t>(functions[static_cast<std::size_t>(r)])]);
  }
  std::vector<detail::DeckNodeSet> sets;
  for (std::size_t label = 0; label < model.labels.size(); ++label)
    for (std::size_t m = 0; m < parts.size(); ++m)
      sets.push_back({model.labels[label], static_cast<int>(m) + 1, {nodes[label][m].begin(), nodes[label][m].end()}});
  detail::write_deck("igaprep Bezier-extraction model: " + std::to_string(model.elements.size()) + " elements, " +
                         std::to_string(parts.size()) + " parts (one per material)",
                     model.materials, part_files, sets, out);
}

}  // namespace igaprep::exporter
