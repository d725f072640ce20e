#pragma once
// What a BEXT 2.0 ASCII part file holds, and its writer (layout and sources:
// docs/export-formats.md). bext.cpp fills it from a multipatch's patches,
// bext_extraction.cpp from a model in Bezier-extraction form (T-splines).
#include <Eigen/Core>
#include <array>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace igaprep::exporter::detail {

// The distinct rows of the extraction operators of elements with the same
// degrees: one dense coefficient block. Rows equal to 1e-13 (the same knot
// pattern at other knot values, equal up to round-off) are one vector.
struct BextDenseBlock {
  std::array<int, 3> degrees{};
  std::map<std::vector<long long>, long long> id_of;  // rounded entries -> 0-based id within the block
  std::vector<std::vector<double>> vectors;
};

// An element: its nodes (1-based, ascending) and for each the id of its
// coefficient vector, 0-based within the block's dense block (the writer
// numbers them on across the dense blocks).
struct BextElement {
  std::vector<long long> nodes, vectors;
};

// Elements with the same degrees and the same number of nodes.
struct BextElementBlock {
  std::array<int, 3> degrees{};
  std::size_t dense = 0;  // index into BextFile::dense
  std::vector<BextElement> elements;
};

struct BextFile {
  int pid = 1;
  std::string comment;                  // the second line, after "$# igaprep: "
  std::vector<Eigen::Vector4d> nodes;   // Cartesian x, y, z and the weight
  std::vector<BextElementBlock> blocks;
  std::vector<BextDenseBlock> dense;
};

// The element with nodes `node_ids` (1-based, in the order of C's rows) and
// extraction operator C (rows: those nodes; columns: Bernstein functions, u
// fastest): nodes sorted, their rows found in or added to `dense`.
BextElement bext_element(const std::vector<long long>& node_ids, const Eigen::MatrixXd& C, BextDenseBlock& dense);

// The index of the dense block of these degrees in f, added when missing.
std::size_t dense_block_for(BextFile& f, const std::array<int, 3>& degrees);

void write_bext_file(const BextFile& f, std::ostream& out);

}  // namespace igaprep::exporter::detail
