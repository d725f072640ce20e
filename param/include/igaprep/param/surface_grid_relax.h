#pragma once
// A block side's sample grid on T1, relaxed on the surface. A spread shell
// face's streamline ends can fold on T1 where a fan turns within a cell: the
// end map is nearly singular there, and moving the streamlines' start
// parameters cannot unfold their ends (docs/decomposition.md, "Spread
// columns"). Here the grid's inner points are moved on the surface itself,
// each towards the mean of its four neighbours and back onto the surface,
// with the grid's border fixed (shared with the neighbouring blocks).
#include <vector>

#include <Eigen/Core>

#include "igaprep/param/surface_projector.h"

namespace igaprep::param {

struct SurfaceGridRelaxOptions {
  int rounds = 30;  // Gauss-Seidel sweeps over the inner points, at most
  // Only the points of folded cells and of this many rings of cells around
  // them move (-1: every inner point). Relaxing more undoes the spreading
  // that follows T1's bulges (docs/decomposition.md, "Spread columns").
  int rings = 1;
  // A point's move is refused when the surface's normal where it lands
  // turns from its old one by more than this cosine allows: across a thin
  // wall the closest point can be on the other side.
  double min_normal_cosine = 0.5;
};

struct SurfaceGridRelaxResult {
  std::vector<Eigen::Vector3d> grid;  // m x m, first index fastest; the border as given
  int folded_before = 0;              // cells folded on the surface, before and after
  int folded_after = 0;
};

// The cells of an m x m grid on a surface (first index fastest) that are
// folded: a corner whose two edges turn against the surface's normal there,
// the grid's orientation taken from the majority of corners.
int count_folded_on_surface(const std::vector<Eigen::Vector3d>& grid, int m, const SurfaceProjector& surface);

// Inputs: grid, m x m points on the surface. Each inner point moves (in
// order, one sweep a round) to the closest surface point of the mean of its
// four neighbours, unless that folds one of its four cells that was not
// folded, or crosses to a part of the surface facing away. Stops when no
// point moves by more than 1e-6 of the grid's size. Deterministic.
SurfaceGridRelaxResult relax_grid_on_surface(const std::vector<Eigen::Vector3d>& grid, int m,
                                            const SurfaceProjector& surface,
                                            const SurfaceGridRelaxOptions& options = {});

}  // namespace igaprep::param
