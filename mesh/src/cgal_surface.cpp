#include "cgal_surface.h"

#include <algorithm>
#include <Eigen/Geometry>
#include <cstdint>
#include <unordered_set>
#include <vector>

#include "igaprep/core/union_find.h"

namespace igaprep::mesh::detail {

SurfaceTopology surface_topology(const TriMesh& mesh) {
  const int nv = static_cast<int>(mesh.V.rows());
  UnionFind vertex_sets(nv);  // vertices used by triangles, joined along edges
  std::vector<char> used(nv, 0);
  std::unordered_set<std::uint64_t> edges;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    for (int c = 0; c < 3; ++c) {
      const int a = mesh.F(f, c), b = mesh.F(f, (c + 1) % 3);
      used[a] = 1;
      vertex_sets.unite(a, b);
      const std::uint64_t lo = std::min(a, b), hi = std::max(a, b);
      edges.insert(lo * static_cast<std::uint64_t>(nv) + hi);
    }
  }
  int used_vertices = 0, components = 0;
  for (int v = 0; v < nv; ++v) {
    if (!used[v]) continue;
    ++used_vertices;
    if (vertex_sets.find(v) == v) ++components;
  }
  const long chi = static_cast<long>(used_vertices) - static_cast<long>(edges.size()) + mesh.F.rows();
  SurfaceTopology t;
  t.components = components;
  t.genus = static_cast<int>((2L * components - chi) / 2);
  return t;
}

}  // namespace igaprep::mesh::detail
