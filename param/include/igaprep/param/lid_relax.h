#pragma once
// The core's lids unfolded over M. Each lid point is the end of a straight
// ray from M to the level w0; where M bends faster than the rays are long
// (a bump of M narrower than the core is thick, a rectangle squeezed by the
// (u, v) map), neighbouring rays cross and the core's ruled cells fold
// (docs/decomposition.md, "Lids unfolded"). Here such a rectangle's lid
// points are re-aimed: first each side where it turns back along its
// length, as a function of the side's own points (the rectangles sharing
// it must agree), then the inner points around the folded cells, at a
// discrete harmonic grid of the lid. Every re-aimed point is where its
// new ray meets the level.
#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include <Eigen/Core>

namespace igaprep::param {

// The end of the ray from `from` along `dir` at the lid's level, or none
// where the ray fails (it leaves the solid).
using LidRay = std::function<std::optional<Eigen::Vector3d>(const Eigen::Vector3d& from, const Eigen::Vector3d& dir)>;

// The cells (i, j) of the ruled block between base and lid (m x m grids,
// first index fastest) whose corner volume, at the lid or halfway to it,
// has the opposite sign from the one at the base.
int count_folded_lid_cells(const std::vector<Eigen::Vector3d>& base, const std::vector<Eigen::Vector3d>& lid, int m);

// The grid indices of side 0 (j = 0), 1 (j = m - 1), 2 (i = 0) or 3
// (i = m - 1) of an m x m grid, in the order of the side's parameter.
std::vector<std::size_t> lid_side_indices(int m, int side);

// One side of a lid (its grid indices in order; the ends fixed), where it
// turns back along its length: each run of folded segments re-aimed along
// the chord between the nearest points around it that keep their order,
// kept if the side's folded segments become fewer. A function of the
// side's own points only; still, rectangles that share a side relax it
// once and copy it (volume_param.cpp): their samples of one side can
// differ in round-off, and a fold judged on one of them only splits it.
void relax_lid_side(const std::vector<Eigen::Vector3d>& base, std::vector<Eigen::Vector3d>& lid,
                    const std::vector<std::size_t>& side, const LidRay& ray);

// Per group of folded cells that touch: the inner points of its cells and
// of 1, 2, 4, ... (up to max_rings) rings around them, re-aimed at a
// discrete harmonic grid (each point the mean of its four neighbours, the
// rest fixed), each try kept if it leaves fewer folded cells. Returns
// the folded cells left.
int relax_lid_inside(const std::vector<Eigen::Vector3d>& base, std::vector<Eigen::Vector3d>& lid, int m,
                     const LidRay& ray, int max_rings = 8);

}  // namespace igaprep::param
