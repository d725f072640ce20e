#pragma once
// Topological and global checks of a multipatch model:
//  - interface conformity: the largest gap between control points that an
//    interface matches (spline::check_conformity);
//  - watertightness: every patch side is exactly one of: an interface side,
//    a labelled boundary side, or collapsed (zero area, as at a pole);
//  - material volumes: each patch's volume by Gauss quadrature of det J,
//    summed per material and per region between nested input surfaces,
//    compared with the volumes the input surfaces enclose.
#include <string>
#include <vector>

#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::iga_check {

// Generalized winding number of a closed mesh at x (1 inside, 0 outside).
double winding_number(const mesh::TriMesh& m, const Eigen::Vector3d& x);

// Integral of det J over the patch (Gauss quadrature per element: exact for
// B-spline patches, 3p+3 points per direction for rational ones).
double patch_volume(const spline::Patch& p);

// Area of a patch side (Gauss quadrature of |x_s x x_t|).
double side_area(const spline::Patch& p, spline::Side side);

struct SideStatus {
  int patch = 0;
  spline::Side side;
  std::string kind;  // "interface", "boundary", "collapsed", "missing", "duplicate"
};

struct RegionVolume {
  int region = 0;              // between surface `region` and `region + 1` (the last: inside it)
  double input_volume = 0.0;   // from the triangle meshes
  double spline_volume = 0.0;  // sum of the patches whose centre lies in the region
  int patches = 0;
  double relative_difference = 0.0;  // (spline - input) / input
};

struct TopologyReport {
  double interface_max_gap = 0.0;           // model units
  double interface_max_gap_relative = 0.0;  // / diagonal
  bool conforming = true;
  std::vector<std::string> conformity_problems;
  bool watertight = true;
  std::vector<SideStatus> sides;           // every side of every patch
  std::vector<std::string> watertight_problems;
  std::vector<double> patch_volumes;
  std::vector<double> material_volumes;    // per model material
  std::vector<RegionVolume> regions;       // empty without surfaces
  std::vector<int> patch_region;           // per patch, -1 when outside every surface
};

// Inputs: model; input surfaces outermost first (may be empty); diagonal
// (relative tolerances; model_diagonal when <= 0); conformity tolerance
// relative to the diagonal.
TopologyReport topology_checks(const spline::MultiPatch& mp, const std::vector<mesh::TriMesh>& surfaces,
                               double diagonal = 0.0, double conformity_tolerance = 1e-9);

}  // namespace igaprep::iga_check
