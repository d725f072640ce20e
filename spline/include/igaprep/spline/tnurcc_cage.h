#pragma once
// The control cage of one surface of a model, the input of a T-NURCC
// (Sederberg, Zheng, Bakenov, Nasri 2003, section 7): the control nets of
// the patch sides that stand for the surface (boundary sides with its label,
// material interfaces lying on it), joined where the patches share control
// points. A quad mesh whose extraordinary vertices are the layout's corners;
// every edge carries a knot interval (opposite edges of a face equal) and a
// crease sharpness. docs/tnurcc.md describes it.
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "igaprep/spline/multipatch.h"

namespace igaprep::spline {

// OpenSubdiv's Sdc::Crease::SHARPNESS_INFINITE: an edge of this sharpness is
// a crease, the limit surface only C0 across it.
inline constexpr double kInfiniteSharpness = 10.0;

struct CageEdge {
  std::array<int, 2> vertices{{0, 0}};
  double interval = 1.0;   // knot interval, > 0
  double sharpness = 0.0;  // 0: smooth; kInfiniteSharpness: a crease
  std::array<int, 2> faces{{-1, -1}};  // the faces it borders; faces[1] = -1 on a border edge
};

// Where a cage face came from: a patch side, and the (i, j) index of each
// corner in the side's control net, i along the side's first tangent
// direction (Side::tangent_directions()).
struct CageFaceOrigin {
  int patch = 0;
  Side side;
  std::array<std::array<int, 2>, 4> net{};
};

struct Cage {
  Eigen::MatrixXd points;                      // #V x 3
  std::vector<std::array<int, 4>> faces;       // counter-clockwise seen from outside
  std::vector<CageEdge> edges;                 // each undirected edge once
  std::vector<std::array<int, 4>> face_edges;  // edge k of face f joins corners k and k + 1
  std::vector<CageFaceOrigin> origin;          // per face (empty for a cage not made from a model)
};

struct CageOptions {
  // A patch edge across which the model's side nets turn by more than this
  // (degrees, the angle between the net's faces on either side) is a crease.
  // 60: the coarse built-in meshes turn by up to 37 degrees between
  // neighbouring triangles where the shape is smooth.
  double crease_angle = 60.0;
  // Every interval 1 whatever the knots: the cage as a Catmull-Clark cage.
  // For models with non-uniform knots (a reduced model), whose limit
  // surface is not evaluated yet (OpenSubdiv's limit is Catmull-Clark's;
  // refine_cage has the non-uniform rules).
  bool equal_intervals = false;
};

// Inputs: a conforming model and a label (index into mp.labels). Output: the
// cage, its faces oriented outward (out of the patches on a boundary, out
// of the inner material on an interface). Knot intervals:
// each side's knot vectors scaled to [0, 1], edge (P_i, P_{i+1}) of an odd
// degree p net taking U[i + (p+1)/2 + 1] - U[i + (p+1)/2]; the zero
// intervals of the clamped ends become the nearest interior interval, so
// that the surface is smooth across patch edges unless they are creases.
// Throws bad_input when no side stands for the label, a degree is even,
// or the sides meet more than two at an edge.
Cage surface_cage(const MultiPatch& mp, int label, const CageOptions& options = {});

// Builds the edge table (and face_edges) of a cage from its faces, every
// interval 1, every edge smooth. Throws bad_input for a face with repeated
// corners or an edge of more than two faces.
void build_cage_edges(Cage& cage);

// One line per face whose opposite edges carry different intervals
// (relative difference above `tolerance`): the T-NURCC opposite-edge rule.
std::vector<std::string> opposite_edge_violations(const Cage& cage, double tolerance = 1e-12);

// Number of edges at each vertex.
std::vector<int> vertex_valences(const Cage& cage);

// True when every edge carries the same interval (to `tolerance` relative).
bool uniform_intervals(const Cage& cage, double tolerance = 1e-12);

}  // namespace igaprep::spline
