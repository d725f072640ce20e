#include "igaprep/param/w_field.h"

#include <string>

#include "igaprep/core/error.h"
#include "igaprep/param/stiffness_matrix.h"

namespace igaprep::param {

HarmonicSolverOptions w_field_default_options() {
  HarmonicSolverOptions o;
  o.solver = LinearSolverKind::ConjugateGradient;
  o.cg_tolerance = 1e-12;
  return o;
}

WField w_field(const DecompositionMesh& H, HarmonicSolverOptions options) {
  const int n = H.num_surfaces;
  if (n < 1 || static_cast<int>(H.surface_vertex_offset.size()) != n + 2)
    throw bad_input("w_field: H has no surface vertex ranges (build it with decomposition_mesh)");
  const Eigen::Index nv = H.tets.V.rows();
  if (H.surface_vertex_offset.back() > nv) throw bad_input("w_field: H's surface vertex ranges exceed its vertices");
  WField out;
  out.K = tet_stiffness(H.tets.V, H.tets.T);
  out.is_dirichlet.assign(static_cast<std::size_t>(nv), 0);
  // One Dirichlet set per surface, from the vertex ranges tetrahedralize
  // keeps (every input vertex, also one no triangle uses, keeps its value).
  std::vector<std::vector<int>> sets(static_cast<std::size_t>(n) + 1);
  std::vector<double> values(static_cast<std::size_t>(n) + 1);
  for (int k = 0; k <= n; ++k) {
    for (int v = H.surface_vertex_offset[k]; v < H.surface_vertex_offset[k + 1]; ++v) {
      sets[static_cast<std::size_t>(k)].push_back(v);
      out.is_dirichlet[static_cast<std::size_t>(v)] = 1;
    }
    values[static_cast<std::size_t>(k)] = w_boundary_value(k, n);
  }
  const HarmonicSolver solver(out.K, sets, options);
  out.w = solver.solve(values);
  out.num_free = solver.num_free();
  out.cg_iterations = solver.last_cg_iterations();
  out.min_value = out.w.minCoeff();
  out.max_value = out.w.maxCoeff();
  out.extrema = find_interior_extrema(out.K, out.w, out.is_dirichlet, 1e-9);
  // Streamlines of -grad w would be caught at them (obtuse tets break the
  // discrete maximum principle): each takes its neighbours' mean.
  if (!out.extrema.empty()) out.flattened = flatten_interior_extrema(out.K, out.w, out.is_dirichlet, 1e-9);
  return out;
}

}  // namespace igaprep::param
