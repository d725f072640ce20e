#include "igaprep/mesh/to_surface_mesh.h"

#include <vector>

namespace igaprep::mesh {

namespace {

// Why a mesh did not convert: nothing (it did), or the first triangle at fault.
struct Refusal {
  bool refused = false;
  std::string why;
};

// Fills sm with the mesh's vertices and triangles, in index order; stops at
// the first triangle CGAL cannot add.
Refusal add_mesh(const TriMesh& mesh, SurfaceMesh& sm) {
  if ((mesh.V.rows() > 0 && mesh.V.cols() != 3) || (mesh.F.rows() > 0 && mesh.F.cols() != 3))
    return {true, "not a triangle mesh in 3D (V has " + std::to_string(mesh.V.cols()) + " columns, F has " +
                      std::to_string(mesh.F.cols()) + ")"};
  std::vector<SurfaceMesh::Vertex_index> vid(static_cast<std::size_t>(mesh.V.rows()));
  for (Eigen::Index i = 0; i < mesh.V.rows(); ++i)
    vid[static_cast<std::size_t>(i)] = sm.add_vertex(CgalPoint(mesh.V(i, 0), mesh.V(i, 1), mesh.V(i, 2)));
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    for (int c = 0; c < 3; ++c)
      if (mesh.F(f, c) < 0 || mesh.F(f, c) >= mesh.V.rows())
        return {true, "triangle " + std::to_string(f) + " has an out-of-range vertex index"};
    auto v = [&](int c) { return vid[static_cast<std::size_t>(mesh.F(f, c))]; };
    if (sm.add_face(v(0), v(1), v(2)) == SurfaceMesh::null_face())
      return {true, "triangle " + std::to_string(f) + " makes the surface non-manifold or inconsistently oriented"};
  }
  return {};
}

}  // namespace

std::optional<SurfaceMesh> try_to_surface_mesh(const TriMesh& mesh) {
  SurfaceMesh sm;
  if (add_mesh(mesh, sm).refused) return std::nullopt;
  return sm;
}

SurfaceMesh to_surface_mesh(const TriMesh& mesh, const std::string& what) {
  SurfaceMesh sm;
  const Refusal r = add_mesh(mesh, sm);
  if (r.refused) throw bad_input(what + ": " + r.why);
  return sm;
}

TriMesh from_surface_mesh(const SurfaceMesh& sm) {
  TriMesh out;
  std::vector<int> index(sm.number_of_vertices() + sm.number_of_removed_vertices(), -1);
  out.V.resize(sm.number_of_vertices(), 3);
  int n = 0;
  for (auto v : sm.vertices()) {
    const CgalPoint& p = sm.point(v);
    out.V.row(n) << p.x(), p.y(), p.z();
    index[v.idx()] = n++;
  }
  out.F.resize(sm.number_of_faces(), 3);
  int f = 0;
  for (auto face : sm.faces()) {
    int c = 0;
    for (auto v : CGAL::vertices_around_face(sm.halfedge(face), sm)) out.F(f, c++) = index[v.idx()];
    ++f;
  }
  return out;
}

}  // namespace igaprep::mesh
