#include "igaprep/iga_check/surface_fit_pairs.h"

#include "igaprep/core/error.h"
#include "igaprep/spline/evaluate.h"
#include "model_faces.h"
#include "surface_distance.h"

namespace igaprep::iga_check {

void detail::face_pairs(const std::vector<ModelFace>& faces, const mesh::TriMesh& mesh, int samples_per_element,
                        int tessellation_per_element, int newton_iterations,
                        const std::function<void(int, const Eigen::Vector2d&, const Eigen::Vector3d&)>& pair) {
  if (samples_per_element < 2 || tessellation_per_element < 1)
    throw bad_input("surface_fit_pairs: samples_per_element must be >= 2 and tessellation_per_element >= 1");
  if (faces.empty()) return;
  if (mesh.F.rows() == 0) throw bad_input("surface_fit_pairs: the surface has no triangles");

  // face -> mesh
  const Triangles tris = mesh_triangles(mesh.V, mesh.F);
  Tree mesh_tree(tris.begin(), tris.end());
  mesh_tree.accelerate_distance_queries();
  for (size_t fi = 0; fi < faces.size(); ++fi) {
    const ModelFace& f = faces[fi];
    const std::array<std::vector<double>, 2> params{
        {element_grid(f.surface.knots[0], samples_per_element), element_grid(f.surface.knots[1], samples_per_element)}};
    const spline::GridEvaluation ev = spline::evaluate_grid(f.surface, params, 0);
    const int nu = static_cast<int>(params[0].size());
    for (int i = 0; i < ev.points.rows(); ++i) {
      const Eigen::Vector3d x = ev.points.row(i).transpose();
      pair(static_cast<int>(fi), {params[0][static_cast<size_t>(i % nu)], params[1][static_cast<size_t>(i / nu)]},
           vec(mesh_tree.closest_point(pt(x))));
    }
  }

  // mesh -> face, from the triangles' centroids: points on the faceted surface,
  // as the face samples' targets are (mesh vertices would pull a smooth face
  // outside a convex faceted surface and add volume)
  const FaceTessellation tess = tessellate_faces(faces, tessellation_per_element);
  Tree tess_tree(tess.triangles.begin(), tess.triangles.end());
  tess_tree.accelerate_distance_queries();
  for (int t = 0; t < mesh.F.rows(); ++t) {
    const Eigen::Vector3d x =
        (mesh.V.row(mesh.F(t, 0)) + mesh.V.row(mesh.F(t, 1)) + mesh.V.row(mesh.F(t, 2))).transpose() / 3.0;
    const FacePoint fp = nearest_face_point(faces, tess, tess_tree, x, newton_iterations);
    pair(fp.face, fp.uv, x);
  }
}

std::vector<spline::SurfaceFitPair> surface_fit_pairs(const spline::MultiPatch& mp, int surface,
                                                      const mesh::TriMesh& mesh,
                                                      const SurfaceFitPairOptions& options) {
  const std::vector<detail::ModelFace> faces = detail::faces_of_surface(mp, surface);
  std::vector<spline::SurfaceFitPair> out;
  detail::face_pairs(faces, mesh, options.samples_per_element, options.tessellation_per_element, options.newton_iterations,
                     [&](int f, const Eigen::Vector2d& uv, const Eigen::Vector3d& target) {
                       out.push_back({faces[static_cast<size_t>(f)].distance.patch, faces[static_cast<size_t>(f)].distance.side, uv, target});
                     });
  return out;
}

std::vector<spline::ExtractionFitPair> extraction_fit_pairs(const spline::ExtractionModel& m, int surface,
                                                            const mesh::TriMesh& mesh,
                                                            const SurfaceFitPairOptions& options) {
  const std::vector<detail::ModelFace> faces = detail::faces_of_surface(m, surface);
  std::vector<spline::ExtractionFitPair> out;
  detail::face_pairs(faces, mesh, options.samples_per_element, options.tessellation_per_element, options.newton_iterations,
                     [&](int f, const Eigen::Vector2d& uv, const Eigen::Vector3d& target) {
                       out.push_back({faces[static_cast<size_t>(f)].distance.element, faces[static_cast<size_t>(f)].distance.side, uv, target});
                     });
  return out;
}

}  // namespace igaprep::iga_check
