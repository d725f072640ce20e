#pragma once
// Section 4 of the seed paper in order: cut loops on T1, the tet mesh of the
// cut surfaces, the midsurface M0, M0trim and its 2D polycube
// parameterization. Each step is its own function (cut_loops.h,
// midsurface.h, trim_midsurface.h, polycube_2d.h); this runs them with the
// options of a case file's "midsurface" section. The base surface M is made
// from the result by inset_base.h.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "igaprep/mesh/tet_mesh.h"
#include "igaprep/mesh/tetrahedralize.h"
#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/param/cut_loops.h"
#include "igaprep/param/midsurface.h"
#include "igaprep/param/polycube_2d.h"
#include "igaprep/param/trim_midsurface.h"

namespace igaprep::param {

struct MidsurfaceOptions {
  enum class CutKind { Automatic, Plane, Loops, Waypoints };
  CutKind cut = CutKind::Automatic;
  CutPlane plane;                        // CutKind::Plane
  std::vector<std::vector<int>> loops;   // CutKind::Loops: T1 vertex indices
  std::vector<std::vector<Eigen::Vector3d>> waypoints;  // CutKind::Waypoints: points per loop
  std::vector<Eigen::Vector3d> corners;  // corner points (4 per boundary loop of M0trim); empty = automatic
  bool path_lengths = true;              // trace the quality paths (section 4.1)
  mesh::TetgenOptions tetgen;
};

struct MidsurfaceResult {
  CutLoops cut;
  mesh::TetMesh tets;        // of the cut T1 and T2..Tn
  Eigen::VectorXd f;         // the midsurface field on tets
  Midsurface m0;
  PathLengthStats paths;
  TrimmedSheet m0trim;       // after split_boundary_ears (m0_vertex = -1 for the vertices that added)
  Polycube2D polycube;
  std::vector<std::string> tried;  // automatic cut: why each rejected candidate failed
  std::vector<std::string> valid;  // automatic cut: the valid candidates with their scores (the best one is kept)
  bool second_best = false;  // automatic cut: kept for want of a candidate whose map needs no cuts from the
                             // holes' corners and squeezes no part of M0trim
};

// Inputs: surfaces T1..Tn (validated, nested, outward), options, name of T1 for
// messages. Output: every intermediate. Throws bad_input (a bad cut or corner
// set) or check_failed (a folded parameterization) with the reason.
MidsurfaceResult build_midsurface(const std::vector<mesh::TriMesh>& surfaces, const MidsurfaceOptions& options,
                                  const std::string& name = "T1");

}  // namespace igaprep::param
