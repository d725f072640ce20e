#pragma once
// Iso-surface of a piecewise-linear scalar field on a tet mesh.
#include <Eigen/Core>

#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::mesh {

struct IsoSurface {
  TriMesh mesh;        // the iso-surface; vertices shared between tets
  Eigen::MatrixXi edge;  // #mesh.V x 2: tet-mesh vertex indices of the edge each vertex lies on
  Eigen::VectorXd t;     // #mesh.V: position along that edge,
                         // mesh.V.row(i) = (1 - t(i)) V(edge(i,0)) + t(i) V(edge(i,1))
  Eigen::VectorXi tet;   // #mesh.F: the tet each triangle was cut from
};

// Inputs: V (#V x 3), T (#T x 4, positively oriented), field (#V), iso value.
// Triangles are oriented with their normal towards increasing field (decided
// combinatorially from the tet's orientation, not from round-off).
// A vertex with field == iso counts as above: the surface is that of the
// field lowered infinitesimally, so it is a manifold wherever the tet mesh
// is; such vertices give output points with t = 0 or 1 that coincide with
// them (and zero-area triangles next to them). Every cut edge gives one
// output vertex, edge(i, 0) < edge(i, 1).
IsoSurface marching_tets(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T, const Eigen::VectorXd& field,
                         double iso);

}  // namespace igaprep::mesh
