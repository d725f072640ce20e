// BEXT writer: Bezier extraction and global numbering come from the spline
// module, the parts from bext_parts; this file only lays them out.
#include "igaprep/export/bext.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <vector>

#include "igaprep/core/error.h"
#include "igaprep/spline/bezier_extraction.h"
#include "bext_parts.h"
#include "model_checks.h"

namespace igaprep::exporter {

namespace {

std::string real(double x) {
  char buf[40];
  std::snprintf(buf, sizeof(buf), "%24.16e", x);
  return buf;
}
std::string integer(long long i) {
  char buf[24];
  std::snprintf(buf, sizeof(buf), "%8lld", i);
  return buf;
}
void integer_lines(std::ostream& out, const std::vector<long long>& v) {
  for (size_t i = 0; i < v.size(); ++i) out << integer(v[i]) << ((i + 1) % 10 == 0 || i + 1 == v.size() ? "\n" : "");
}

// The distinct coefficient vectors of the part's elements with the same
// degrees: one dense block each. Rows equal to 1e-13 (the same knot pattern
// at other knot values, equal up to round-off) are one vector.
struct DenseBlock {
  std::array<int, 3> degrees{};
  std::map<std::vector<long long>, long long> id_of;  // rounded entries -> 0-based id within the block
  std::vector<std::vector<double>> vectors;
};

struct Element {
  std::vector<long long> nodes, vectors;  // 1-based, nodes ascending
};

// One patch's elements (u fastest), each with its part nodes in ascending
// order and the ids (1-based, across all blocks) of the matching rows of
// its extraction operator; new rows go into the patch's dense block.
std::vector<Element> patch_elements(const spline::Patch& patch, const std::vector<long long>& node_of,
                                    DenseBlock& block) {
  std::vector<Element> out;
  const spline::PatchExtraction ex = spline::bezier_extraction(patch);
  for (int ew = 0; ew < ex.element_count(2); ++ew)
    for (int ev = 0; ev < ex.element_count(1); ++ev)
      for (int eu = 0; eu < ex.element_count(0); ++eu) {
        const std::vector<int> local = spline::element_control_points(patch, ex, eu, ev, ew);
        const Eigen::MatrixXd C = spline::element_extraction_operator(ex, eu, ev, ew);
        std::vector<std::size_t> order(local.size());
        std::iota(order.begin(), order.end(), 0);
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
          return node_of[static_cast<std::size_t>(local[a])] < node_of[static_cast<std::size_t>(local[b])];
        });
        Element e;
        for (const std::size_t r : order) {
          e.nodes.push_back(node_of[static_cast<std::size_t>(local[r])]);
          std::vector<double> row;
          std::vector<long long> key;
          for (Eigen::Index c = 0; c < C.cols(); ++c) {
            row.push_back(C(static_cast<Eigen::Index>(r), c));
            key.push_back(std::llround(row.back() * 1e13));
          }
          const auto [it, added] = block.id_of.emplace(key, static_cast<long long>(block.vectors.size()));
          if (added) block.vectors.push_back(std::move(row));
          e.vectors.push_back(it->second);  // made global below, once the blocks' sizes are known
        }
        out.push_back(std::move(e));
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
  // Patches grouped by degrees: one dense block per group.
  std::vector<DenseBlock> blocks;
  std::vector<std::size_t> block_of_patch;
  std::vector<std::vector<Element>> elements;
  for (std::size_t i = 0; i < part.patches.size(); ++i) {
    const spline::Patch& patch = model.patches[static_cast<std::size_t>(part.patches[i])];
    auto b = std::find_if(blocks.begin(), blocks.end(), [&](const DenseBlock& x) { return x.degrees == patch.degrees; });
    if (b == blocks.end()) b = blocks.insert(blocks.end(), DenseBlock{patch.degrees, {}, {}});
    block_of_patch.push_back(static_cast<std::size_t>(b - blocks.begin()));
    elements.push_back(patch_elements(patch, part.node_of[i], *b));
  }
  std::vector<long long> first_id(blocks.size(), 1);  // vector ids run on across the dense blocks
  for (std::size_t b = 1; b < blocks.size(); ++b)
    first_id[b] = first_id[b - 1] + static_cast<long long>(blocks[b - 1].vectors.size());
  long long num_elements = 0, num_vectors = 0;
  for (const std::vector<Element>& block : elements) num_elements += static_cast<long long>(block.size());
  for (const DenseBlock& b : blocks) num_vectors += static_cast<long long>(b.vectors.size());

  const spline::Material& mat = model.materials[static_cast<std::size_t>(material)];
  out << "B E X T 2.0\n";
  out << "$# igaprep: part " << part.pid << ", material '" << mat.name << "', " << part.patches.size()
      << " patches (element block b = the part's b-th patch, elements u fastest)\n";
  out << "$#   pid      nn      ne     ncv     wfl\n";
  out << integer(part.pid) << integer(static_cast<long long>(part.node_source.size())) << integer(num_elements)
      << integer(num_vectors) << integer(1) << "\n";
  out << "$#                    Xi                      Yi                      Zi                      Wi\n";
  for (const auto& [p, l] : part.node_source) {
    const spline::Patch& patch = model.patches[static_cast<std::size_t>(p)];
    out << real(patch.control_points(l, 0)) << real(patch.control_points(l, 1)) << real(patch.control_points(l, 2))
        << real(patch.rational() ? patch.weights[l] : 1.0) << "\n";
  }
  out << "$#   NEB\n" << integer(static_cast<long long>(part.patches.size())) << "\n";
  out << "$# ETYPE      NE      NN     NCV      PR      PS      PT\n";
  for (std::size_t i = 0; i < part.patches.size(); ++i) {
    const std::array<int, 3>& d = model.patches[static_cast<std::size_t>(part.patches[i])].degrees;
    const long long nn = (d[0] + 1LL) * (d[1] + 1) * (d[2] + 1);
    out << integer(1) << integer(static_cast<long long>(elements[i].size())) << integer(nn) << integer(nn)
        << integer(d[0]) << integer(d[1]) << integer(d[2]) << "\n";
  }
  out << "$#  NIDS ... CVIDS\n";
  for (std::size_t i = 0; i < elements.size(); ++i)
    for (Element& e : elements[i]) {
      for (long long& v : e.vectors) v += first_id[block_of_patch[i]];
      integer_lines(out, e.nodes);
      integer_lines(out, e.vectors);
    }
  out << "$# NDCVB   NSCVB\n" << integer(static_cast<long long>(blocks.size())) << integer(0) << "\n";
  out << "$#  NCVd   NCVCd\n";
  for (const DenseBlock& b : blocks) {
    const std::array<int, 3>& d = b.degrees;
    out << integer(static_cast<long long>(b.vectors.size())) << integer((d[0] + 1LL) * (d[1] + 1) * (d[2] + 1)) << "\n";
  }
  out << "$#                  CVCm\n";
  for (const DenseBlock& b : blocks)
    for (const std::vector<double>& v : b.vectors)
      for (std::size_t c = 0; c < v.size(); ++c) out << real(v[c]) << ((c + 1) % 5 == 0 || c + 1 == v.size() ? "\n" : "");
  out << "$#END FILE\n";
}

}  // namespace igaprep::exporter
