#include "igaprep/param/boundary_traces.h"

#include <algorithm>
#include <string>

#include <Eigen/Geometry>

#include "igaprep/core/error.h"
#include "igaprep/param/tet_topology.h"

namespace igaprep::param {

Eigen::VectorXd path_field_values(const GradientTracer& tracer, const Eigen::MatrixXi& T, const Eigen::VectorXd& u,
                                  const Eigen::MatrixXd& path) {
  Eigen::VectorXd out(path.rows());
  int hint = -1;
  for (Eigen::Index i = 0; i < path.rows(); ++i) {
    Eigen::Vector4d b;
    hint = tracer.locate(path.row(i).transpose(), hint, &b);
    if (hint < 0) throw internal_error("path_field_values: path point " + std::to_string(i) + " lies in no tet");
    double v = 0.0;
    for (int k = 0; k < 4; ++k) v += b(k) * u(T(hint, k));
    out(i) = v;
  }
  return out;
}

namespace {

Eigen::MatrixXd vertex_normals(const mesh::TriMesh& M) {
  Eigen::MatrixXd N = Eigen::MatrixXd::Zero(M.V.rows(), 3);
  for (Eigen::Index f = 0; f < M.F.rows(); ++f) {
    const Eigen::Vector3d a = M.V.row(M.F(f, 0)), b = M.V.row(M.F(f, 1)), c = M.V.row(M.F(f, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a);  // twice the area times the unit normal
    for (int k = 0; k < 3; ++k) N.row(M.F(f, k)) += n.transpose();
  }
  for (Eigen::Index i = 0; i < N.rows(); ++i) {
    const double l = N.row(i).norm();
    if (l > 0) N.row(i) /= l;
  }
  return N;
}

}  // namespace

BoundaryTraces trace_boundaries(const DecompositionMesh& H, const WField& w, const BaseSurface& M,
                                const BoundaryTraceOptions& options) {
  const int n = H.num_surfaces;
  const Eigen::MatrixXd& V = H.tets.V;
  const Eigen::MatrixXi& T = H.tets.T;
  if (w.w.size() != V.rows()) throw bad_input("trace_boundaries: the w-field was computed on another mesh");
  if (H.base_faces.rows() != M.mesh.F.rows() ||
      H.surface_vertex_offset[static_cast<std::size_t>(n) + 1] - H.surface_vertex_offset[static_cast<std::size_t>(n)] !=
          M.mesh.V.rows())
    throw bad_input("trace_boundaries: M is not the base surface embedded in H");

  const TetTopology topo = build_tet_topology(T, V.rows());
  const std::vector<int>& t1 = H.surface_faces.at(0);
  Eigen::MatrixXi F1(static_cast<Eigen::Index>(t1.size()), 3);
  for (std::size_t i = 0; i < t1.size(); ++i) F1.row(static_cast<Eigen::Index>(i)) = H.tets.F.row(t1[i]);
  TraceTarget target;
  target.marked = mark_facets(T, topo, F1);
  const GradientTracer tracer(V, T, topo, w.w);
  TraceOptions topt = options.trace;
  topt.descend = true;

  BoundaryTraces out;
  // A trace can stall on a valley edge next to a vertex of Ti (seen on ring2
  // for 2 of 466 side traces). Resuming from where it stopped starts the
  // tracer's search afresh there; w keeps decreasing, so the joined path is
  // still monotone. Bounded by options.resume_stalled.
  auto resume = [&](TraceResult r) {
    for (int k = 0; k < options.resume_stalled && r.status == TraceStatus::Stalled; ++k) {
      TraceResult next = tracer.trace(r.cell, r.bary, target, topt);
      if (!(next.value < r.value)) break;  // no progress: a real critical point
      Eigen::MatrixXd path(r.path.rows() + next.path.rows() - 1, 3);
      path << r.path, next.path.bottomRows(next.path.rows() - 1);
      next.path = std::move(path);
      next.steps += r.steps;
      r = std::move(next);
      ++out.resumed;
    }
    return r;
  };
  auto record = [&](BoundaryTrace& bt) {
    bt.trace = resume(std::move(bt.trace));
    // The end is known exactly (cell and barycentric coordinates); a point on
    // T1 could fail the point location by round-off.
    const Eigen::Index np = bt.trace.path.rows();
    bt.w.resize(np);
    if (np > 1) bt.w.head(np - 1) = path_field_values(tracer, T, w.w, bt.trace.path.topRows(np - 1));
    bt.w(np - 1) = bt.trace.value;
    bt.max_rise = 0.0;
    for (Eigen::Index i = 0; i + 1 < bt.w.size(); ++i) bt.max_rise = std::max(bt.max_rise, bt.w(i + 1) - bt.w(i));
    ++out.total;
    out.reached += bt.trace.status == TraceStatus::Reached;
    ++out.status_count[static_cast<std::size_t>(bt.trace.status)];
  };
  // From an M vertex itself: a vertex of H, so start in any tet around it.
  auto from_vertex = [&](int m_vertex) {
    BoundaryTrace bt;
    bt.vertex = m_vertex;
    const int hv = decomposition_vertex(H, n, m_vertex);
    const int s = topo.vertex_cells_start[static_cast<std::size_t>(hv)];
    if (s == topo.vertex_cells_start[static_cast<std::size_t>(hv) + 1])
      throw internal_error("trace_boundaries: vertex " + std::to_string(m_vertex) + " of M is in no tet of H");
    const int c = topo.vertex_cells[static_cast<std::size_t>(s)];
    Eigen::Vector4d b = Eigen::Vector4d::Zero();
    for (int k = 0; k < 4; ++k) b(k) = T(c, k) == hv ? 1.0 : 0.0;
    bt.trace = tracer.trace(c, b, target, topt);
    record(bt);
    return bt;
  };
  auto from_point = [&](int m_vertex, const Eigen::Vector3d& p) {
    BoundaryTrace bt;
    bt.vertex = m_vertex;
    Eigen::Vector4d b;
    const int hv = decomposition_vertex(H, n, m_vertex);
    const int c = tracer.locate(p, topo.vertex_cells[static_cast<std::size_t>(topo.vertex_cells_start[hv])], &b);
    if (c < 0) throw internal_error("trace_boundaries: side start point next to M vertex " + std::to_string(m_vertex) +
                                    " lies in no tet (offset too large?)");
    bt.trace = tracer.trace(c, b, target, topt);
    record(bt);
    return bt;
  };

  for (const auto& loop : M.boundary_loops) {
    out.loops.emplace_back();
    for (int v : loop) out.loops.back().push_back(from_vertex(v));
  }
  for (const auto& cs : M.corners) {
    out.corners.emplace_back();
    for (int k = 0; k < 4; ++k) out.corners.back()[static_cast<std::size_t>(k)] = from_vertex(cs[static_cast<std::size_t>(k)]);
  }
  if (options.side_offset > 0) {
    const double e = options.side_offset * (V.colwise().maxCoeff() - V.colwise().minCoeff()).norm();
    const Eigen::MatrixXd N = vertex_normals(M.mesh);
    for (const auto& loop : M.boundary_loops) {
      out.plus.emplace_back();
      out.minus.emplace_back();
      for (int v : loop) {
        const Eigen::Vector3d p = M.mesh.V.row(v), nv = N.row(v);
        out.plus.back().push_back(from_point(v, p + e * nv));
        out.minus.back().push_back(from_point(v, p - e * nv));
      }
    }
  }
  return out;
}

}  // namespace igaprep::param
