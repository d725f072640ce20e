#pragma once
// Smoothness of a surface of the model: the angle between the normals on
// either side of an edge, for the C0 multipatch (across its patch edges)
// and for the T-NURCC limit surface of its cage (across every cage edge).
// Crease edges are left out of both: they are meant to be sharp.
#include <Eigen/Core>

#include "igaprep/spline/multipatch.h"
#include "igaprep/spline/tnurcc_cage.h"
#include "igaprep/spline/tnurcc_limit.h"

namespace igaprep::spline {

struct NormalJumps {
  long points = 0;           // places measured
  double max = 0.0;          // degrees
  double mean = 0.0;         // degrees
  double max_gap = 0.0;      // largest distance between the two sides' points (a check on the pairing)
  Eigen::Vector3d max_location = Eigen::Vector3d::Zero();
};

// The model's side surfaces on either side of each cage edge that joins two
// patch sides, evaluated at `samples` points along the edge (between the
// Greville abscissae of its end points). Input: the cage from surface_cage
// on the same model.
NormalJumps model_normal_jumps(const MultiPatch& mp, const Cage& cage, int samples = 3);

// Which cage edges limit_normal_jumps measures.
enum class JumpEdges {
  smooth,              // every edge that is not a crease
  smooth_patch_edges,  // those of them that join two patch sides (where model_normal_jumps measures)
  creases,             // the creases alone
};

// The limit surface's normals from the two faces of each chosen edge, at
// `samples` points along it.
NormalJumps limit_normal_jumps(const Cage& cage, JumpEdges edges, int samples = 3, const LimitOptions& options = {});

}  // namespace igaprep::spline
