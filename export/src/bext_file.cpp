#include "bext_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "igaprep/core/error.h"

namespace igaprep::exporter::detail {

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

void integer_lines(std::ostream& out, const std::vector<long long>& v, long long offset = 0) {
  for (std::size_t i = 0; i < v.size(); ++i)
    out << integer(v[i] + offset) << ((i + 1) % 10 == 0 || i + 1 == v.size() ? "\n" : "");
}

long long bernstein_count(const std::array<int, 3>& d) { return (d[0] + 1LL) * (d[1] + 1) * (d[2] + 1); }

}  // namespace

BextElement bext_element(const std::vector<long long>& node_ids, const Eigen::MatrixXd& C, BextDenseBlock& dense) {
  std::vector<std::size_t> order(node_ids.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return node_ids[a] < node_ids[b]; });
  BextElement e;
  for (const std::size_t r : order) {
    e.nodes.push_back(node_ids[r]);
    std::vector<double> row;
    std::vector<long long> key;
    for (Eigen::Index c = 0; c < C.cols(); ++c) {
      row.push_back(C(static_cast<Eigen::Index>(r), c));
      key.push_back(std::llround(row.back() * 1e13));
    }
    const auto [it, added] = dense.id_of.emplace(key, static_cast<long long>(dense.vectors.size()));
    if (added) dense.vectors.push_back(std::move(row));
    e.vectors.push_back(it->second);
  }
  return e;
}

std::size_t dense_block_for(BextFile& f, const std::array<int, 3>& degrees) {
  for (std::size_t b = 0; b < f.dense.size(); ++b)
    if (f.dense[b].degrees == degrees) return b;
  f.dense.push_back(BextDenseBlock{degrees, {}, {}});
  return f.dense.size() - 1;
}

void write_bext_file(const BextFile& f, std::ostream& out) {
  std::vector<long long> first_id(f.dense.size(), 1);  // vector ids run on across the dense blocks
  for (std::size_t b = 1; b < f.dense.size(); ++b)
    first_id[b] = first_id[b - 1] + static_cast<long long>(f.dense[b - 1].vectors.size());
  long long num_elements = 0, num_vectors = 0;
  for (const BextElementBlock& b : f.blocks) num_elements += static_cast<long long>(b.elements.size());
  for (const BextDenseBlock& b : f.dense) num_vectors += static_cast<long long>(b.vectors.size());

  out << "B E X T 2.0\n";
  out << "$# igaprep: " << f.comment << "\n";
  out << "$#   pid      nn      ne     ncv     wfl\n";
  out << integer(f.pid) << integer(static_cast<long long>(f.nodes.size())) << integer(num_elements)
      << integer(num_vectors) << integer(1) << "\n";
  out << "$#                    Xi                      Yi                      Zi                      Wi\n";
  for (const Eigen::Vector4d& x : f.nodes) out << real(x[0]) << real(x[1]) << real(x[2]) << real(x[3]) << "\n";
  out << "$#   NEB\n" << integer(static_cast<long long>(f.blocks.size())) << "\n";
  out << "$# ETYPE      NE      NN     NCV      PR      PS      PT\n";
  for (const BextElementBlock& b : f.blocks) {
    const long long nn = b.elements.empty() ? bernstein_count(b.degrees) : static_cast<long long>(b.elements[0].nodes.size());
    for (const BextElement& e : b.elements)
      if (static_cast<long long>(e.nodes.size()) != nn) throw internal_error("BEXT: an element block mixes node counts");
    out << integer(1) << integer(static_cast<long long>(b.elements.size())) << integer(nn) << integer(nn)
        << integer(b.degrees[0]) << integer(b.degrees[1]) << integer(b.degrees[2]) << "\n";
  }
  out << "$#  NIDS ... CVIDS\n";
  for (const BextElementBlock& b : f.blocks)
    for (const BextElement& e : b.elements) {
      integer_lines(out, e.nodes);
      integer_lines(out, e.vectors, first_id[b.dense]);
    }
  out << "$# NDCVB   NSCVB\n" << integer(static_cast<long long>(f.dense.size())) << integer(0) << "\n";
  out << "$#  NCVd   NCVCd\n";
  for (const BextDenseBlock& b : f.dense)
    out << integer(static_cast<long long>(b.vectors.size())) << integer(bernstein_count(b.degrees)) << "\n";
  out << "$#                  CVCm\n";
  for (const BextDenseBlock& b : f.dense)
    for (const std::vector<double>& v : b.vectors)
      for (std::size_t c = 0; c < v.size(); ++c) out << real(v[c]) << ((c + 1) % 5 == 0 || c + 1 == v.size() ? "\n" : "");
  out << "$#END FILE\n";
}

}  // namespace igaprep::exporter::detail
