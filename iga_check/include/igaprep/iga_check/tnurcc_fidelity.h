#pragma once
// Fidelity of a T-NURCC limit surface to a triangle mesh, both ways, and the
// point pairs that fit a cage to the mesh (spline/tnurcc_fit.h):
//  - limit -> mesh: an n x n grid of limit points per cage face to the mesh,
//    exact point-triangle distances (CGAL AABB tree);
//  - mesh -> limit: every mesh vertex to the limit surface: the nearest
//    point of a tessellation of the limit surface, then one Gauss-Newton
//    step on the limit surface itself; the distance is to a point of the
//    limit surface, so it is never below the true distance.
#include <vector>

#include "igaprep/iga_check/fidelity.h"
#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/spline/tnurcc_cage.h"
#include "igaprep/spline/tnurcc_fit.h"

namespace igaprep::iga_check {

struct LimitFidelityOptions {
  int samples_per_face = 4;       // limit -> mesh: per direction, at the centres of an n x n split
  int tessellation_per_face = 6;  // mesh -> limit: quads per direction and face
  spline::LimitOptions limit;
};

struct LimitFidelity {
  DistanceStats limit_to_mesh, mesh_to_limit;
};

// Relative figures divide by `diagonal` (the mesh's bounding-box diagonal when <= 0).
LimitFidelity limit_fidelity(const spline::Cage& cage, const mesh::TriMesh& mesh, double diagonal = 0.0,
                             const LimitFidelityOptions& options = {});

// The pairs of both directions above: each limit sample with its closest
// mesh point, each mesh vertex with its nearest limit location.
std::vector<spline::FitPair> limit_mesh_pairs(const spline::Cage& cage, const mesh::TriMesh& mesh,
                                              const LimitFidelityOptions& options = {});

}  // namespace igaprep::iga_check
