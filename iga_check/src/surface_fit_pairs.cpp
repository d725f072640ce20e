#include "igaprep/iga_check/surface_fit_pairs.h"

#include "igaprep/core/error.h"
#include "igaprep/spline/evaluate.h"
#include "model_faces.h"
#include "surface_distance.h"

namespace igaprep::iga_check {

std::vector<spline::SurfaceFitPair> surface_fit_pairs(const spline::MultiPatch& mp, int surface,
                                                      const mesh::TriMesh& mesh,
                                                      const SurfaceFitPairOptions& options) {
  if (options.samples_per_element < 2 || options.tessellation_per_element < 1)
    throw bad_input("surface_fit_pairs: samples_per_element must be >= 2 and tessellation_per_element >= 1");
  const std::vector<detail::ModelFace> faces = detail::faces_of_surface(mp, surface);
  std::vector<spline::SurfaceFitPair> out;
  if (faces.empty()) return out;
  if (mesh.F.rows() == 0) throw bad_input("surface_fit_pairs: surface " + std::to_string(surface) + " has no triangles");
  auto pair = [&](const detail::ModelFace& f, const Eigen::Vector2d& uv, const Eigen::Vector3d& target) {
    out.push_back({f.distance.patch, f.distance.side, uv, target});
  };

  // face -> mesh
  const detail::Triangles tris = detail::mesh_triangles(mesh.V, mesh.F);
  detail::Tree mesh_tree(tris.begin(), tris.end());
  mesh_tree.accelerate_distance_queries();
  for (const detail::ModelFace& f : faces) {
    const std::array<std::vector<double>, 2> params{
        {detail::element_grid(f.surface.knots[0], options.samples_per_element),
         detail::element_grid(f.surface.knots[1], options.samples_per_element)}};
    const spline::GridEvaluation ev = spline::evaluate_grid(f.surface, params, 0);
    const int nu = static_cast<int>(params[0].size());
    for (int i = 0; i < ev.points.rows(); ++i) {
      const Eigen::Vector3d x = ev.points.row(i).transpose();
      pair(f, {params[0][static_cast<size_t>(i % nu)], params[1][static_cast<size_t>(i / nu)]},
           detail::vec(mesh_tree.closest_point(detail::pt(x))));
    }
  }

  // mesh -> face, from the triangles' centroids: points on the faceted surface,
  // as the face samples' targets are (mesh vertices would pull a smooth face
  // outside a convex faceted surface and add volume)
  const detail::FaceTessellation tess = detail::tessellate_faces(faces, options.tessellation_per_element);
  detail::Tree tess_tree(tess.triangles.begin(), tess.triangles.end());
  tess_tree.accelerate_distance_queries();
  for (int t = 0; t < mesh.F.rows(); ++t) {
    const Eigen::Vector3d x =
        (mesh.V.row(mesh.F(t, 0)) + mesh.V.row(mesh.F(t, 1)) + mesh.V.row(mesh.F(t, 2))).transpose() / 3.0;
    const detail::FacePoint fp = detail::nearest_face_point(faces, tess, tess_tree, x, options.newton_iterations);
    pair(faces[static_cast<size_t>(fp.face)], fp.uv, x);
  }
  return out;
}

}  // namespace igaprep::iga_check
