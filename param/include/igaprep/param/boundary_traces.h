#pragma once
// The raw material of the decomposition surfaces (seed paper, sections 5.1
// and 5.2): from every boundary vertex and every corner of the base surface M
// a path along -grad w out to T1 through T2..Tn. The corner paths are the
// spines of the corner surfaces C_j; the boundary paths (and, with an offset,
// the paths from p +- e n on either side of M) those of S+ and S-.
#include <array>
#include <vector>

#include <Eigen/Core>

#include "igaprep/param/base_surface.h"
#include "igaprep/param/decomposition_mesh.h"
#include "igaprep/param/trace_gradient.h"
#include "igaprep/param/w_field.h"

namespace igaprep::param {

struct BoundaryTraceOptions {
  // > 0: also trace from p + e n and p - e n (n: M's area-weighted vertex
  // normal, e = side_offset * bounding-box diagonal of H), the start points of
  // S+ and S- in the paper; 0: only from the boundary vertices themselves.
  double side_offset = 0.0;
  TraceOptions trace;  // `descend` is forced on
  // A stalled trace is resumed from its end point (a fresh start of the
  // tracer there) up to this many times, as long as w still decreases.
  int resume_stalled = 2;
};

struct BoundaryTrace {
  int vertex = -1;       // M vertex the trace starts from (or next to, for side traces)
  TraceResult trace;     // ends on a face of T1 when trace.status == Reached
  Eigen::VectorXd w;     // w at every point of trace.path (path_field_values; the last is trace.value)
  double max_rise = 0.0;  // largest increase of w from one path point to the next (0: monotone)
};

struct BoundaryTraces {
  std::vector<std::vector<BoundaryTrace>> loops;    // per M.boundary_loops, per vertex in loop order
  std::vector<std::array<BoundaryTrace, 4>> corners;  // per M.corners entry, its four corners
  std::vector<std::vector<BoundaryTrace>> plus, minus;  // per loop, when side_offset > 0
  int total = 0, reached = 0;                      // over every trace above
  std::array<int, 4> status_count{};               // traces per TraceStatus
  int resumed = 0;                                 // resumptions of stalled traces (options.resume_stalled)
};

// Inputs: a tracer on H's tets (its field u), the tets, the field, a polyline.
// Output: u interpolated at each point (located by a walk from the previous
// point); throws internal_error when a point lies in no tet.
Eigen::VectorXd path_field_values(const GradientTracer& tracer, const Eigen::MatrixXi& T, const Eigen::VectorXd& u,
                                  const Eigen::MatrixXd& path);

// Inputs: H, its w-field, the base surface M it embeds (the same M as given to
// decomposition_mesh), options. Output: the traces, descending w until a face
// of T1 (marker 0) is reached; every trace ends, with its status.
BoundaryTraces trace_boundaries(const DecompositionMesh& H, const WField& w, const BaseSurface& M,
                                const BoundaryTraceOptions& options = {});

}  // namespace igaprep::param
