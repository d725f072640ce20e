// BEXT writer: Bezier extraction and global numbering come from the spline
// module; this file only lays them out.
#include "igaprep/export/bext.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

#include "igaprep/core/atomic_file.h"
#include "igaprep/core/error.h"
#include "igaprep/spline/bezier_extraction.h"
#include "igaprep/spline/multipatch_topology.h"
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


// Patches with the same degrees: one element block and one dense
// coefficient block each. The coefficient vectors (rows of the elements'
// extraction operators) are written once each: elements refer to them by
// id, and most are shared (sphere2: 2,320 distinct of 359,424).
struct Family {
  std::array<int, 3> degrees{};
  std::vector<int> patches;
  long long elements = 0;
  std::vector<std::vector<double>> vectors;  // distinct, in order of first use
};

struct ElementRecord {
  int patch = 0;
  std::array<int, 3> index{};
  std::vector<long long> nodes, vectors;  // 1-based ids
};

// Global nodes: coordinates and weight from the first patch that has them.
std::vector<std::array<double, 4>> global_nodes(const spline::MultiPatch& model, const spline::GlobalNumbering& numbering) {
  std::vector<std::array<double, 4>> nodes(static_cast<std::size_t>(numbering.count));
  std::vector<bool> set(nodes.size(), false);
  for (std::size_t p = 0; p < model.patches.size(); ++p) {
    const spline::Patch& patch = model.patches[p];
    for (Eigen::Index r = 0; r < patch.control_points.rows(); ++r) {
      const auto g = static_cast<std::size_t>(numbering.global[p][static_cast<std::size_t>(r)]);
      if (set[g]) continue;
      set[g] = true;
      nodes[g] = {patch.control_points(r, 0), patch.control_points(r, 1), patch.control_points(r, 2),
                  patch.rational() ? patch.weights[r] : 1.0};
    }
  }
  return nodes;
}

// Patches grouped by degrees, in order of first appearance.
std::vector<Family> families_of(const spline::MultiPatch& model) {
  std::vector<Family> families;
  for (int p = 0; p < static_cast<int>(model.patches.size()); ++p) {
    const std::array<int, 3> d = model.patches[static_cast<std::size_t>(p)].degrees;
    auto f = std::find_if(families.begin(), families.end(), [&](const Family& x) { return x.degrees == d; });
    if (f == families.end()) f = families.insert(families.end(), Family{d, {}, 0, {}});
    f->patches.push_back(p);
  }
  return families;
}

// Every element of the family's patches, with its nodes and the ids of its
// coefficient vectors (first_id: the id of the family's first vector); the
// family's distinct vectors collected on the way.
std::vector<ElementRecord> family_elements(const spline::MultiPatch& model, const spline::GlobalNumbering& numbering,
                                           Family& family, long long first_id) {
  std::vector<ElementRecord> out;
  // Vectors that differ by round-off only (the same knot pattern at other
  // knot values) are one: keyed by their entries to 1e-13.
  std::map<std::vector<long long>, long long> id_of;
  for (int p : family.patches) {
    const spline::Patch& patch = model.patches[static_cast<std::size_t>(p)];
    const spline::PatchExtraction ex = spline::bezier_extraction(patch);
    for (int ew = 0; ew < ex.element_count(2); ++ew)
      for (int ev = 0; ev < ex.element_count(1); ++ev)
        for (int eu = 0; eu < ex.element_count(0); ++eu) {
          ElementRecord e{p, {eu, ev, ew}, {}, {}};
          for (int l : spline::element_control_points(patch, ex, eu, ev, ew))
            e.nodes.push_back(numbering.global[static_cast<std::size_t>(p)][static_cast<std::size_t>(l)] + 1);
          const Eigen::MatrixXd C = spline::element_extraction_operator(ex, eu, ev, ew);
          for (Eigen::Index r = 0; r < C.rows(); ++r) {
            std::vector<double> row;
            std::vector<long long> key;
            for (Eigen::Index c = 0; c < C.cols(); ++c) {
              row.push_back(C(r, c));
              key.push_back(std::llround(C(r, c) * 1e13));
            }
            const auto [it, added] = id_of.emplace(key, first_id + static_cast<long long>(family.vectors.size()));
            if (added) family.vectors.push_back(std::move(row));
            e.vectors.push_back(it->second);
          }
          out.push_back(std::move(e));
        }
  }
  family.elements = static_cast<long long>(out.size());
  return out;
}
}  // namespace

void write_bext(const spline::MultiPatch& model, std::ostream& out) {
  detail::check_model_for_writing(model, "BEXT");
  const spline::GlobalNumbering numbering = spline::global_numbering(model);
  const std::vector<std::array<double, 4>> nodes = global_nodes(model, numbering);
  std::vector<Family> families = families_of(model);
  std::vector<std::vector<ElementRecord>> elements;
  long long num_elements = 0, num_vectors = 0;
  for (Family& f : families) {
    elements.push_back(family_elements(model, numbering, f, num_vectors + 1));
    num_elements += f.elements;
    num_vectors += static_cast<long long>(f.vectors.size());
  }
  const int np = static_cast<int>(model.patches.size());
  out << "B E X T 2.0\n";
  out << "$ written by igaprep: " << np << " patches, " << model.materials.size()
      << " materials; element blocks = patch families (same degrees); coefficient vectors shared\n";
  for (int p = 0; p < np; ++p)
    out << "$ patch " << p << " material " << model.patches[p].material << " "
        << model.materials[model.patches[p].material].name << "\n";
  out << integer(numbering.count) << integer(num_elements) << integer(num_vectors) << integer(0) << "\n";
  for (const auto& n : nodes) out << real(n[0]) << real(n[1]) << real(n[2]) << real(n[3]) << "\n";
  out << integer(static_cast<long long>(families.size())) << "\n";
  for (const Family& f : families) {
    const auto& d = f.degrees;
    const long long nn = (d[0] + 1) * (d[1] + 1) * (d[2] + 1);
    out << integer(1) << integer(f.elements) << integer(nn) << integer(nn) << integer(d[0]) << integer(d[1])
        << integer(d[2]) << "\n";
  }
  for (const std::vector<ElementRecord>& block : elements)
    for (const ElementRecord& e : block) {
      out << "$ patch " << e.patch << " element " << e.index[0] << " " << e.index[1] << " " << e.index[2] << "\n";
      integer_lines(out, e.nodes);
      integer_lines(out, e.vectors);
    }
  out << integer(static_cast<long long>(families.size())) << "\n";
  for (const Family& f : families) {
    const auto& d = f.degrees;
    out << integer(static_cast<long long>(f.vectors.size())) << integer((d[0] + 1) * (d[1] + 1) * (d[2] + 1)) << "\n";
  }
  for (const Family& f : families)
    for (const std::vector<double>& v : f.vectors)
      for (std::size_t c = 0; c < v.size(); ++c) out << real(v[c]) << ((c + 1) % 5 == 0 || c + 1 == v.size() ? "\n" : "");
}

void write_bext(const spline::MultiPatch& model, const std::string& path) {
  detail::check_model_for_writing(model, "'" + path + "'");
  write_file_atomically(path, [&](std::ostream& out) { write_bext(model, out); });
}

}  // namespace igaprep::exporter
