#pragma once
// Gradient tracing through a tet mesh (or over a triangle surface) along +grad
// or -grad of a piecewise-linear field. The gradient is constant per cell, so
// each step is a straight segment to the exit facet, computed exactly in
// barycentric coordinates. Passing through edges and vertices, cells whose
// gradients point at each other, and cells with a tiny gradient are handled by
// looking at all cells around the point and falling back to the continuous
// vertex-averaged gradient. Every positive step strictly increases (decreases)
// the field, zero-length steps are counted and never repeat a cell, and there
// is a step budget: a trace always ends, with a status saying why.
#include <vector>

#include <Eigen/Core>

#include "igaprep/param/tet_topology.h"

namespace igaprep::param {

enum class TraceStatus {
  Reached,      // reached the target iso-value or a marked facet
  HitBoundary,  // left the mesh through an unmarked boundary facet (or could not slide along it)
  StepBudget,   // max_steps cell crossings done without reaching the target
  Stalled,      // a critical point: no cell around the point lets the field grow (shrink)
};
const char* to_string(TraceStatus status);

struct TraceTarget {
  bool use_iso = false;  // stop where the field reaches `iso`
  double iso = 0.0;
  std::vector<int> marked;  // empty, or from mark_facets(): stop on reaching a marked facet
};

struct TraceOptions {
  bool descend = false;           // follow -grad instead of +grad
  int max_steps = 1000000;        // budget of cell crossings and steps
  bool slide_on_boundary = true;  // at an unmarked boundary facet, follow the gradient projected onto it
                                  // (inside the mesh, sliding along valley facets is always on)
  double tiny_gradient = 1e-10;   // |grad| below this times (field range / mesh size) counts as zero
};

struct TraceResult {
  TraceStatus status = TraceStatus::Stalled;
  Eigen::MatrixXd path;             // n x 3 polyline from the start to the end point
  int cell = -1;                    // cell holding the end point
  int facet = -1;                   // local facet of `cell` the end lies on (the marked facet when reached), or -1
  int face = -1;                    // row of the marked facets (mark_facets input) reached, or -1
  Eigen::Vector4d bary = Eigen::Vector4d::Zero();  // barycentric coordinates of the end in `cell` (3 used for triangles)
  Eigen::Vector3d end = Eigen::Vector3d::Zero();
  double value = 0.0;               // field at the end
  int steps = 0;                    // cells crossed
};

class GradientTracer {
 public:
  // Inputs: V (#V x 3), cells (#C x 4 tets or #C x 3 triangles), their
  // topology, field u (#V). V, cells and topology are referenced, not copied:
  // keep them alive while the tracer is used. Precomputes vertex gradients.
  GradientTracer(const Eigen::MatrixXd& V, const Eigen::MatrixXi& cells, const TetTopology& topology,
                 const Eigen::VectorXd& u);

  // Trace from a point given by cell and barycentric coordinates (3 or 4 used,
  // clamped to >= 0 and normalized).
  TraceResult trace(int cell, const Eigen::Vector4d& bary, const TraceTarget& target,
                    const TraceOptions& options = {}) const;
  // Trace from a point in space (tets only): locates the cell first; throws
  // bad_input when the point is in no tet.
  TraceResult trace(const Eigen::Vector3d& start, const TraceTarget& target, const TraceOptions& options = {}) const;

  // Tet holding point p (walking from `hint`, then a full scan), -1 if none.
  // Writes p's barycentric coordinates to *bary when given.
  int locate(const Eigen::Vector3d& p, int hint = -1, Eigen::Vector4d* bary = nullptr) const;

  const Eigen::MatrixXd& vertex_gradient() const { return vertex_gradient_; }

 private:
  template <int K>
  TraceResult run(int cell, const Eigen::Vector4d& bary, const TraceTarget& target, const TraceOptions& options) const;

  const Eigen::MatrixXd& V_;
  const Eigen::MatrixXi& C_;
  const TetTopology& topo_;
  Eigen::VectorXd u_;
  Eigen::MatrixXd vertex_gradient_;
  double grad_scale_ = 1.0;  // field range / bounding-box diagonal
  double diag_ = 1.0;        // bounding-box diagonal
};

}  // namespace igaprep::param
