#pragma once
// Private to iga_check/: the spline faces of a model that stand for one input
// surface (boundary sides labelled with it, material interfaces lying on it),
// sample grids on them, a tessellation that remembers parameters, and the
// projection of a point onto a face. Shared by the fidelity of a model
// (fidelity.cpp) and the point pairs that fit its faces (surface_fit_pairs.cpp).
#include <Eigen/Core>
#include <array>
#include <functional>
#include <utility>
#include <vector>

#include "igaprep/iga_check/fidelity.h"
#include "igaprep/spline/curve_surface.h"
#include "igaprep/spline/extraction_model.h"
#include "igaprep/spline/multipatch.h"
#include "surface_distance.h"

namespace igaprep::iga_check::detail {

struct ModelFace {
  spline::Surface surface;
  std::array<std::pair<double, double>, 2> domain;
  FaceDistance distance;  // its place in the model; max filled by the spline -> mesh pass
};

// n points per element in each direction, shared element ends once.
std::vector<double> element_grid(const std::vector<double>& U, int n);

// The faces standing for surface `surface`: boundary sides first, then
// interfaces (patch a's side), in the model's order.
std::vector<ModelFace> faces_of_surface(const spline::MultiPatch& mp, int surface);

// The element faces of an extraction model standing for surface `surface`
// (boundary faces, then interface faces), each the Bezier face of its
// element on [0, 1]^2 (FaceDistance::element set).
std::vector<ModelFace> faces_of_surface(const spline::ExtractionModel& m, int surface);

// The fidelity of faces standing for one surface (fidelity.cpp): both ways,
// relative to `diagonal`; the counts of boundary and interface faces set.
SurfaceFidelity measure_faces(std::vector<ModelFace> faces, const mesh::TriMesh& tm, double diagonal,
                              const FidelityOptions& options);

// The fitting pairs of faces standing for one surface (surface_fit_pairs.cpp):
// each face sample with its closest mesh point, each mesh triangle's centroid
// with the faces' point nearest it; `pair` gets (face index, uv, target).
void face_pairs(const std::vector<ModelFace>& faces, const mesh::TriMesh& mesh, int samples_per_element,
                int tessellation_per_element, int newton_iterations,
                const std::function<void(int, const Eigen::Vector2d&, const Eigen::Vector3d&)>& pair);

// Gauss-Newton (with a tiny Levenberg term for collapsed edges) for the
// point of the face nearest x, from the parameter guess uv (replaced by the
// best parameters found); returns the distance.
double project_to_face(const ModelFace& f, const Eigen::Vector3d& x, Eigen::Vector2d& uv, int iterations);

// The faces cut into `per_element` x `per_element` quads per element, two
// triangles each, with each triangle's face and corner parameters.
struct FaceTessellation {
  Triangles triangles;
  std::vector<std::pair<int, std::array<Eigen::Vector2d, 3>>> uv;  // (face, corner parameters) per triangle
};
FaceTessellation tessellate_faces(const std::vector<ModelFace>& faces, int per_element);

// The face and parameters of the faces' point nearest x: the nearest point
// of the tessellation (its tree built over `t.triangles`), then the projection.
struct FacePoint {
  int face = -1;
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
  double distance = 0.0;
};
FacePoint nearest_face_point(const std::vector<ModelFace>& faces, const FaceTessellation& t, const Tree& tree,
                             const Eigen::Vector3d& x, int newton_iterations);

}  // namespace igaprep::iga_check::detail
