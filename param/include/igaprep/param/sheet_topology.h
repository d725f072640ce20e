#pragma once
// Topology of an open triangle sheet (the midsurface M0, M0trim, the base
// surface M): components, manifoldness, Euler characteristic and the ordered
// boundary loops. Used to check that a sheet is "a disc with g holes".
#include <string>
#include <vector>

#include <Eigen/Core>

namespace igaprep::param {

struct SheetTopology {
  int vertices = 0;    // vertices used by some face
  int edges = 0;
  int faces = 0;
  int components = 0;  // connected through shared edges
  bool edge_manifold = false;    // every edge in one or two faces
  bool vertex_manifold = false;  // the faces around every vertex form one fan
  bool oriented = false;         // neighbouring faces agree on orientation
  int euler = 0;                 // vertices - edges + faces
  // Boundary loops, each a closed vertex cycle (first vertex not repeated),
  // following the faces' orientation (the sheet lies to the left).
  std::vector<std::vector<int>> boundary_loops;
};

// Inputs: F (#F x 3) faces; num_vertices (#V). Output: the topology above.
// Never throws for a bad sheet (it is described instead); throws bad_input
// for an index out of range.
SheetTopology analyze_sheet(const Eigen::MatrixXi& F, Eigen::Index num_vertices);

// "" when the sheet is a single, manifold, oriented sheet of genus 0 with
// `expected_loops` boundary loops (a disc with expected_loops - 1 holes);
// otherwise one sentence saying what is wrong, starting with `name`.
std::string describe_sheet_problem(const SheetTopology& topology, int expected_loops, const std::string& name);

}  // namespace igaprep::param
