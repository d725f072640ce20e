#pragma once
// Volumes of a tet mesh, in total and per material.
#include <vector>

#include "igaprep/mesh/tet_mesh.h"

namespace igaprep::mesh {

struct TetVolumes {
  double total = 0.0;                   // signed sum over all tets
  std::vector<double> per_material;     // tets with material m in [0, materials)
  std::vector<long> tets_per_material;
};

// Signed volume of the tet (a, b, c, d): positive when d lies on the side of
// the triangle (a, b, c) its counter-clockwise normal points to.
double signed_tet_volume(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                         const Eigen::Vector3d& d);

// Inputs: a tet mesh with a material per tet, the number of materials.
// Tets with a material outside [0, materials) count in the total only.
TetVolumes tet_volumes(const TetMesh& tets, int materials);

}  // namespace igaprep::mesh
