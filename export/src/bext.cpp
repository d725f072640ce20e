// BEXT part files of a multipatch: Bezier extraction and global numbering
// come from the spline module, the parts from bext_parts, the layout from
// bext_file.
#include "igaprep/export/bext.h"

#include <vector>

#include "igaprep/core/error.h"
#include "igaprep/spline/bezier_extraction.h"
#include "bext_file.h"
#include "bext_parts.h"
#include "model_checks.h"

namespace igaprep::exporter {

namespace {

// One patch's elements (u fastest) as one element block.
detail::BextElementBlock patch_block(const spline::Patch& patch, const std::vector<long long>& node_of,
                                     std::size_t dense, detail::BextDenseBlock& block) {
  detail::BextElementBlock out{patch.degrees, dense, {}};
  const spline::PatchExtraction ex = spline::bezier_extraction(patch);
  for (int ew = 0; ew < ex.element_count(2); ++ew)
    for (int ev = 0; ev < ex.element_count(1); ++ev)
      for (int eu = 0; eu < ex.element_count(0); ++eu) {
        std::vector<long long> nodes;
        for (const int l : spline::element_control_points(patch, ex, eu, ev, ew))
          nodes.push_back(node_of[static_cast<std::size_t>(l)]);
        out.elements.push_back(detail::bext_element(nodes, spline::element_extraction_operator(ex, eu, ev, ew), block));
      }
  return out;
}

}  // namespace

std::vector<std::string> bext_paths(const std::string& basename, int materials) {
  std::vector<std::string> out{basename + ".k"};
  for (int pid = 1; pid <= materials; ++pid) out.push_back(basename + "_part" + std::to_string(pid) + ".bext");
  return out;
}

void write_bext_part(const spline::MultiPatch& model, int material, std::ostream& out) {
  detail::check_model_for_writing(model, "BEXT");
  if (material < 0 || material >= static_cast<int>(model.materials.size()))
    throw bad_input("BEXT: no material " + std::to_string(material) + " in a model of " +
                    std::to_string(model.materials.size()));
  const detail::BextPart part = detail::bext_parts(model)[static_cast<std::size_t>(material)];
  detail::BextFile f;
  f.pid = part.pid;
  f.comment = "part " + std::to_string(part.pid) + ", material '" + model.materials[static_cast<std::size_t>(material)].name +
              "', " + std::to_string(part.patches.size()) + " patches (element block b = the part's b-th patch, elements u fastest)";
  for (const auto& [p, l] : part.node_source) {
    const spline::Patch& patch = model.patches[static_cast<std::size_t>(p)];
    f.nodes.emplace_back(patch.control_points(l, 0), patch.control_points(l, 1), patch.control_points(l, 2),
                         patch.rational() ? patch.weights[l] : 1.0);
  }
  for (std::size_t i = 0; i < part.patches.size(); ++i) {
    const spline::Patch& patch = model.patches[static_cast<std::size_t>(part.patches[i])];
    const std::size_t dense = detail::dense_block_for(f, patch.degrees);  // patches grouped by degrees
    f.blocks.push_back(patch_block(patch, part.node_of[i], dense, f.dense[dense]));
  }
  detail::write_bext_file(f, out);
}

}  // namespace igaprep::exporter
