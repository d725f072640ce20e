#pragma once
// Values and smoothed gradients of a P1 field on a tet mesh at arbitrary
// points, the first point along a ray where the field falls to a level, and
// the walk that finds the tet holding a point. The volume layout uses it to
// find the iso-surface T(n+1) = {w = w0} around the base surface M and to
// follow -grad w out to T1 (streamline_column.h).
#include <limits>
#include <memory>

#include <Eigen/Core>

#include "igaprep/param/tet_topology.h"

namespace igaprep::param {

namespace detail {
class TetGrid;
}

class FieldProbe {
 public:
  // Inputs: V, tets, their topology, the field (#V) and its per-vertex
  // gradients (#V x 3, vertex_gradients()). All referenced, not copied.
  FieldProbe(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T, const TetTopology& topology,
             const Eigen::VectorXd& u, const Eigen::MatrixXd& vertex_gradient);

  // The tet holding p: without a hint (null or -1) a look-up in a grid of
  // the tets, else a walk from *hint (locate_in_tets), with a scan when
  // it cycles, or when it leaves the mesh and no hint was given; -1 when a
  // walk from a hint leaves the mesh through its boundary (the steps of rays
  // and streamlines are short) or no tet holds p. *hint receives the tet found; *bary its barycentric coordinates.
  int locate(const Eigen::Vector3d& p, int* hint, Eigen::Vector4d* bary) const;

  // u at p (NaN outside the mesh).
  double value(const Eigen::Vector3d& p, int* hint = nullptr) const;

  // A smoother u at p: the barycentric blend of the first-order Taylor
  // expansions at the tet's four vertices (with the vertex gradients).
  // Exact for quadratic u where the vertex gradients are; its level sets
  // have no kinks at the tet faces (those of the P1 u do). NaN outside.
  double smooth_value(const Eigen::Vector3d& p, int* hint = nullptr) const;

  // The vertex gradients interpolated linearly at p: a continuous field,
  // whose streamlines never merge (those of the per-tet gradient do, on
  // valley edges). In a tet with a vertex on the ridge (set_ridge) the
  // tet's own gradient is used instead: the vertex gradient of a ridge
  // vertex averages both sides and points nowhere. Returns false outside
  // the mesh.
  bool gradient(const Eigen::Vector3d& p, int* hint, Eigen::Vector3d* g) const;

  // Vertices with u >= value form a ridge (the base surface M for w = 1).
  void set_ridge(double value) { ridge_ = value; }

  // Inputs: start (u(start) > level), unit direction, level, step (march
  // length), max_length. Output: the first point of the ray where the
  // smooth u (smooth_value) = level
  // (the first march step that reaches it, then bisection to 1e-12 of the
  // step). A point where the walk from the last step leaves the mesh is
  // looked up afresh (a grid of the tets): the way to a point inside can
  // cross a re-entrant edge of the boundary. Throws check_failed when the
  // ray leaves the mesh or runs
  // max_length without reaching the level.
  // *hint: a tet near start (receives the last tet visited).
  Eigen::Vector3d ray_to_level(const Eigen::Vector3d& start, const Eigen::Vector3d& direction, double level,
                               double step, double max_length, int* hint = nullptr) const;

 private:
  const Eigen::MatrixXd& V_;
  const Eigen::MatrixXi& T_;
  const TetTopology& topo_;
  const Eigen::VectorXd& u_;
  const Eigen::MatrixXd& grad_;
  std::shared_ptr<const detail::TetGrid> grid_;  // shared by copies
  double ridge_ = std::numeric_limits<double>::infinity();
};

}  // namespace igaprep::param
