// BEXT writer: Bezier extraction and global numbering come from the spline
// module; this file only lays them out.
#include "igaprep/export/bext.h"

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
}  // namespace

void write_bext(const spline::MultiPatch& model, std::ostream& out) {
  detail::check_model_for_writing(model, "BEXT");
  const spline::GlobalNumbering numbering = spline::global_numbering(model);
  const int np = static_cast<int>(model.patches.size());

  // Global nodes: coordinates and weight from the first patch that has them.
  std::vector<std::array<double, 4>> nodes(numbering.count);
  std::vector<bool> set(numbering.count, false);
  for (int p = 0; p < np; ++p) {
    const spline::Patch& patch = model.patches[p];
    for (Eigen::Index r = 0; r < patch.control_points.rows(); ++r) {
      const int g = numbering.global[p][r];
      if (set[g]) continue;
      set[g] = true;
      nodes[g] = {patch.control_points(r, 0), patch.control_points(r, 1), patch.control_points(r, 2),
                  patch.rational() ? patch.weights[r] : 1.0};
    }
  }
  // Families: patches with the same degrees, in order of first appearance.
  std::vector<std::array<int, 3>> family_degrees;
  std::vector<std::vector<int>> family_patches;
  for (int p = 0; p < np; ++p) {
    const std::array<int, 3> d = model.patches[p].degrees;
    size_t f = 0;
    while (f < family_degrees.size() && family_degrees[f] != d) ++f;
    if (f == family_degrees.size()) {
      family_degrees.push_back(d);
      family_patches.emplace_back();
    }
    family_patches[f].push_back(p);
  }
  std::vector<spline::PatchExtraction> ex;
  long long num_elements = 0;
  for (int p = 0; p < np; ++p) {
    ex.push_back(spline::bezier_extraction(model.patches[p]));
    num_elements += ex.back().element_count();
  }
  long long num_vectors = 0;
  std::vector<long long> block_elements(family_degrees.size(), 0);
  for (size_t f = 0; f < family_degrees.size(); ++f) {
    const auto& d = family_degrees[f];
    for (int p : family_patches[f]) block_elements[f] += ex[p].element_count();
    num_vectors += block_elements[f] * (d[0] + 1) * (d[1] + 1) * (d[2] + 1);
  }

  out << "B E X T 2.0\n";
  out << "$ written by igaprep: " << np << " patches, " << model.materials.size()
      << " materials; element blocks = patch families (same degrees)\n";
  for (int p = 0; p < np; ++p)
    out << "$ patch " << p << " material " << model.patches[p].material << " "
        << model.materials[model.patches[p].material].name << "\n";
  out << integer(numbering.count) << integer(num_elements) << integer(num_vectors) << integer(0) << "\n";
  for (const auto& n : nodes) out << real(n[0]) << real(n[1]) << real(n[2]) << real(n[3]) << "\n";
  out << integer(static_cast<long long>(family_degrees.size())) << "\n";
  for (size_t f = 0; f < family_degrees.size(); ++f) {
    const auto& d = family_degrees[f];
    const long long nn = (d[0] + 1) * (d[1] + 1) * (d[2] + 1);
    out << integer(1) << integer(block_elements[f]) << integer(nn) << integer(nn) << integer(d[0]) << integer(d[1])
        << integer(d[2]) << "\n";
  }
  long long next_vector = 1;
  for (size_t f = 0; f < family_degrees.size(); ++f)
    for (int p : family_patches[f]) {
      const spline::Patch& patch = model.patches[p];
      for (int ew = 0; ew < ex[p].element_count(2); ++ew)
        for (int ev = 0; ev < ex[p].element_count(1); ++ev)
          for (int eu = 0; eu < ex[p].element_count(0); ++eu) {
            out << "$ patch " << p << " element " << eu << " " << ev << " " << ew << "\n";
            const std::vector<int> local = spline::element_control_points(patch, ex[p], eu, ev, ew);
            std::vector<long long> ids, vecs;
            for (int l : local) {
              ids.push_back(numbering.global[p][l] + 1);
              vecs.push_back(next_vector++);
            }
            integer_lines(out, ids);
            integer_lines(out, vecs);
          }
    }
  out << integer(static_cast<long long>(family_degrees.size())) << "\n";
  for (size_t f = 0; f < family_degrees.size(); ++f) {
    const auto& d = family_degrees[f];
    const long long nn = (d[0] + 1) * (d[1] + 1) * (d[2] + 1);
    out << integer(block_elements[f] * nn) << integer(nn) << "\n";
  }
  for (size_t f = 0; f < family_degrees.size(); ++f)
    for (int p : family_patches[f])
      for (int ew = 0; ew < ex[p].element_count(2); ++ew)
        for (int ev = 0; ev < ex[p].element_count(1); ++ev)
          for (int eu = 0; eu < ex[p].element_count(0); ++eu) {
            const Eigen::MatrixXd C = spline::element_extraction_operator(ex[p], eu, ev, ew);
            for (Eigen::Index r = 0; r < C.rows(); ++r)
              for (Eigen::Index c = 0; c < C.cols(); ++c)
                out << real(C(r, c)) << ((c + 1) % 5 == 0 || c + 1 == C.cols() ? "\n" : "");
          }
}

void write_bext(const spline::MultiPatch& model, const std::string& path) {
  detail::check_model_for_writing(model, "'" + path + "'");
  write_file_atomically(path, [&](std::ostream& out) { write_bext(model, out); });
}

}  // namespace igaprep::exporter
