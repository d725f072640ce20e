// The LS-DYNA keyword deck beside the BEXT part files (bext.h). Fixed
// 10-column fields; card layouts as docs/export-formats.md cites them.
#include <algorithm>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include "bext_parts.h"
#include "lsdyna_deck.h"
#include "igaprep/core/error.h"
#include "igaprep/export/bext.h"
#include "igaprep/spline/curve_surface.h"
#include "model_checks.h"

namespace igaprep::exporter {

namespace {

std::string field(long long i) {
  char buf[24];
  std::snprintf(buf, sizeof(buf), "%10lld", i);
  return buf;
}

// A positive real in 10 columns with as many digits as fit.
std::string field(double x) {
  char buf[40];
  for (int digits = 7; digits >= 1; --digits) {
    std::snprintf(buf, sizeof(buf), "%10.*g", digits, x);
    if (std::string(buf).size() <= 10) return buf;
  }
  throw bad_input("LS-DYNA deck: " + std::string(buf) + " does not fit a 10-column field");
}

std::string title(const std::string& s) { return s.substr(0, 80); }

// The part's nodes (1-based) on the boundary sides with `label`, ascending.
std::vector<long long> label_nodes(const spline::MultiPatch& model, const detail::BextPart& part, int label) {
  std::set<long long> nodes;
  for (const spline::BoundarySide& b : model.boundaries) {
    if (b.label != label) continue;
    const auto at = std::find(part.patches.begin(), part.patches.end(), b.patch);
    if (at == part.patches.end()) continue;
    const std::vector<long long>& node_of = part.node_of[static_cast<std::size_t>(at - part.patches.begin())];
    for (const int l : spline::side_control_points(model.patches[static_cast<std::size_t>(b.patch)], b.side))
      nodes.insert(node_of[static_cast<std::size_t>(l)]);
  }
  return {nodes.begin(), nodes.end()};
}

void write_part(const spline::Material& mat, int material, int pid, const std::string& file, std::ostream& out) {
  out << "*PART\n$# title\n" << title(mat.name.empty() ? "material " + std::to_string(material) : mat.name) << "\n";
  out << "$#     pid     secid       mid\n" << field(static_cast<long long>(pid)) << field(static_cast<long long>(pid))
      << field(static_cast<long long>(pid)) << "\n";
  out << "*SECTION_IGA_SOLID\n$#   secid\n" << field(static_cast<long long>(pid)) << "\n";
  out << "*MAT_ELASTIC\n$#     mid        ro         e        pr\n" << field(static_cast<long long>(pid))
      << field(1.0) << field(mat.young_modulus) << field(mat.poisson_ratio) << "\n";
  out << "*IGA_INCLUDE_BEZIER\n" << file << "\n$#    type       pid       dim\n" << field(1LL)
      << field(static_cast<long long>(pid)) << field(3LL) << "\n";
}

}  // namespace

namespace detail {

void write_deck(const std::string& heading, const std::vector<spline::Material>& materials,
                const std::vector<std::string>& part_files, const std::vector<DeckNodeSet>& sets, std::ostream& out) {
  if (part_files.size() != materials.size())
    throw bad_input("LS-DYNA deck: " + std::to_string(part_files.size()) + " part files for " +
                    std::to_string(materials.size()) + " materials");
  out << "*KEYWORD\n*TITLE\n" << title(heading) << "\n";
  out << "$ Units are the model's (E in them). RO (density) is not in the model: 1.0 is written, set it\n"
         "$ for dynamics. Parts share no nodes: each BEXT file numbers its control points 1..n,\n"
         "$ and the node sets below use those numbers (docs/export-formats.md).\n";
  for (std::size_t m = 0; m < materials.size(); ++m)
    write_part(materials[m], static_cast<int>(m), static_cast<int>(m) + 1, part_files[m], out);
  long long sid = 0;
  for (const DeckNodeSet& set : sets) {
    if (set.nodes.empty()) continue;
    out << "*SET_NODE_LIST_TITLE\n"
        << title(set.label + " (part " + std::to_string(set.pid) + ", " + part_files[static_cast<std::size_t>(set.pid - 1)] + ")")
        << "\n$#     sid\n"
        << field(++sid) << "\n";
    for (std::size_t i = 0; i < set.nodes.size(); ++i)
      out << field(set.nodes[i]) << ((i + 1) % 8 == 0 || i + 1 == set.nodes.size() ? "\n" : "");
  }
  out << "*END\n";
}

}  // namespace detail

void write_lsdyna_deck(const spline::MultiPatch& model, const std::vector<std::string>& part_files, std::ostream& out) {
  detail::check_model_for_writing(model, "LS-DYNA deck");
  const std::vector<detail::BextPart> parts = detail::bext_parts(model);
  std::vector<detail::DeckNodeSet> sets;
  for (std::size_t label = 0; label < model.labels.size(); ++label)
    for (const detail::BextPart& part : parts)
      sets.push_back({model.labels[label], part.pid, label_nodes(model, part, static_cast<int>(label))});
  detail::write_deck("igaprep model: " + std::to_string(model.patches.size()) + " patches, " +
                         std::to_string(parts.size()) + " parts (one per material)",
                     model.materials, part_files, sets, out);
}

}  // namespace igaprep::exporter
