#pragma once
// A bijective (u, v) map onto a domain with holes (polycube_2d.h): a
// harmonic map onto a domain with holes may fold next to the holes' reflex
// corners. Cut from every hole corner straight out, turning the same way
// round each hole (a pinwheel), to the first thing met (the outer rectangle,
// another hole or an earlier cut): every part of the domain is then a
// rectangle, convex, and a convex-combination map onto each is bijective
// (Tutte, Floater) once the cuts' sheet paths are fixed on their lines.
#include <vector>

#include <Eigen/Core>

#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/param/polycube_2d.h"

namespace igaprep::param::detail {

// Finds a sheet path per hole corner into pc.hole_cuts (the corner first,
// ending on the outer loop, a hole's loop or an earlier path), each
// touching no boundary vertex or earlier path between its ends. For a domain
// with holes and no arms. False (pc.hole_cuts cleared) when a cut has no path.
bool find_hole_cuts(const mesh::TriMesh& sheet, Polycube2D& pc);

// Fixes a sheet path on the segment a -> b of the domain: its vertices'
// (u, v) spread by 3D arc length (a cut, an arm's neck).
void spread_on_segment(const mesh::TriMesh& sheet, const std::vector<int>& path, const Eigen::Vector2d& a,
                       const Eigen::Vector2d& b, Eigen::MatrixXd& uv, std::vector<char>& fixed);

// Fixes each cut's vertices on the straight line between its ends' (u, v)
// (set before: boundary vertices, earlier cuts), spread by 3D arc length.
void fix_hole_cuts(const mesh::TriMesh& sheet, const Polycube2D& pc, Eigen::MatrixXd& uv, std::vector<char>& fixed);

}  // namespace igaprep::param::detail
