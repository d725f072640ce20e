#include "igaprep/iga_check/fidelity.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "igaprep/core/error.h"
#include "igaprep/core/union_find.h"
#include "igaprep/spline/curve_surface.h"
#include "igaprep/spline/evaluate.h"
#include "igaprep/spline/knot_vector.h"
#include "model_faces.h"
#include "surface_distance.h"

namespace igaprep::iga_check {

using detail::element_grid;
using detail::pt;
using detail::summarize;
using detail::Tree;
using detail::Triangles;

double mesh_diagonal(const mesh::TriMesh& m) {
  if (m.V.rows() == 0) return 0.0;
  return (m.V.colwise().maxCoeff() - m.V.colwise().minCoeff()).norm();
}

std::vector<UncoveredRegion> uncovered_regions(const mesh::TriMesh& mesh, const std::vector<double>& distance,
                                               double limit) {
  const int n = static_cast<int>(mesh.V.rows());
  if (static_cast<int>(distance.size()) != n)
    throw bad_input("uncovered_regions: " + std::to_string(distance.size()) + " distances for " + std::to_string(n) +
                    " vertices");
  auto far = [&](int v) { return distance[static_cast<size_t>(v)] > limit; };
  UnionFind sets(n);
  for (int f = 0; f < mesh.F.rows(); ++f)
    for (int e = 0; e < 3; ++e) {
      const int a = mesh.F(f, e), b = mesh.F(f, (e + 1) % 3);
      if (far(a) && far(b)) sets.unite(a, b);
    }
  std::map<int, UncoveredRegion> by_root;
  for (int v = 0; v < n; ++v) {
    if (!far(v)) continue;
    UncoveredRegion& r = by_root[sets.find(v)];
    const Eigen::Vector3d x = mesh.V.row(v).transpose();
    ++r.vertices;
    r.centroid += x;
    if (r.vertices == 1 || distance[static_cast<size_t>(v)] > r.max) {
      r.max = distance[static_cast<size_t>(v)];
      r.farthest = x;
    }
  }
  std::vector<UncoveredRegion> out;
  for (auto& [root, r] : by_root) {
    r.centroid /= r.vertices;
    out.push_back(r);
  }
  std::stable_sort(out.begin(), out.end(), [](const UncoveredRegion& a, const UncoveredRegion& b) { return a.max > b.max; });
  return out;
}

double model_diagonal(const spline::MultiPatch& mp) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const spline::Patch& p : mp.patches) {
    std::array<std::vector<double>, 3> params;
    for (int d = 0; d < 3; ++d) params[d] = element_grid(p.knots[d], 3);
    const Eigen::MatrixXd X = spline::evaluate_grid_points(p, spline::grid_basis(p, params, 0));
    for (int i = 0; i < X.rows(); ++i) {
      lo = lo.cwiseMin(X.row(i).transpose());
      hi = hi.cwiseMax(X.row(i).transpose());
    }
  }
  return mp.patches.empty() ? 0.0 : (hi - lo).norm();
}

SurfaceFidelity detail::measure_faces(std::vector<detail::ModelFace> faces, const mesh::TriMesh& tm, double diagonal,
                                      const FidelityOptions& options) {
  SurfaceFidelity sf;
  for (const auto& f : faces) {
    if (f.distance.interface)
      ++sf.interface_faces;
    else
      ++sf.boundary_faces;
  }
  // spline -> mesh
  const Triangles mesh_tris = detail::mesh_triangles(tm.V, tm.F);
  Tree mesh_tree(mesh_tris.begin(), mesh_tris.end());
  mesh_tree.accelerate_distance_queries();
  std::vector<double> d1;
  std::vector<Eigen::Vector3d> w1;
  for (detail::ModelFace& f : faces) {
    std::array<std::vector<double>, 2> params{{element_grid(f.surface.knots[0], options.samples_per_element),
                                               element_grid(f.surface.knots[1], options.samples_per_element)}};
    const spline::GridEvaluation ev = spline::evaluate_grid(f.surface, params, 0);
    for (int i = 0; i < ev.points.rows(); ++i) {
      const Eigen::Vector3d x = ev.points.row(i).transpose();
      const double d = std::sqrt(mesh_tree.squared_distance(pt(x)));
      d1.push_back(d);
      w1.push_back(x);
      if (d > f.distance.max || i == 0) {
        f.distance.max = d;
        f.distance.max_location = x;
      }
    }
    sf.faces.push_back(f.distance);
  }
  sf.spline_to_mesh = summarize(d1, w1, diagonal);

  // mesh -> spline
  const detail::FaceTessellation tess = detail::tessellate_faces(faces, options.tessellation_per_element);
  Tree tess_tree(tess.triangles.begin(), tess.triangles.end());
  tess_tree.accelerate_distance_queries();
  std::vector<double> d2;
  std::vector<Eigen::Vector3d> w2;
  for (int v = 0; v < tm.V.rows(); ++v) {
    const Eigen::Vector3d x = tm.V.row(v).transpose();
    d2.push_back(detail::nearest_face_point(faces, tess, tess_tree, x, options.newton_iterations).distance);
    w2.push_back(x);
  }
  sf.mesh_to_spline = summarize(d2, w2, diagonal);
  sf.vertex_distance = std::move(d2);
  return sf;
}

namespace {

// The fidelity of each surface some face stands for, faces_of(surface) giving them.
template <class FacesOf>
std::vector<SurfaceFidelity> fidelity_of(const FacesOf& faces_of, const std::vector<std::string>& labels,
                                         const std::vector<mesh::TriMesh>& surfaces, double diagonal,
                                         const FidelityOptions& options) {
  if (options.samples_per_element < 2 || options.tessellation_per_element < 1)
    throw bad_input("fidelity: samples_per_element must be >= 2 and tessellation_per_element >= 1");
  std::vector<SurfaceFidelity> out;
  for (size_t si = 0; si < surfaces.size(); ++si) {
    if (options.only_surface >= 0 && static_cast<int>(si) != options.only_surface) continue;
    std::vector<detail::ModelFace> faces = faces_of(static_cast<int>(si));
    if (faces.empty()) continue;
    if (surfaces[si].F.rows() == 0) throw bad_input("fidelity: input surface " + std::to_string(si) + " has no triangles");
    SurfaceFidelity sf = detail::measure_faces(std::move(faces), surfaces[si], diagonal, options);
    sf.surface = static_cast<int>(si);
    if (si < labels.size()) sf.label = labels[si];
    out.push_back(std::move(sf));
  }
  return out;
}

}  // namespace

std::vector<SurfaceFidelity> fidelity(const spline::MultiPatch& mp, const std::vector<mesh::TriMesh>& surfaces,
                                      double diagonal, const FidelityOptions& options) {
  if (!(diagonal > 0.0)) diagonal = model_diagonal(mp);
  if (!(diagonal > 0.0)) throw bad_input("fidelity: the model has no extent");
  return fidelity_of([&](int s) { return detail::faces_of_surface(mp, s); }, mp.labels, surfaces, diagonal, options);
}

double model_diagonal(const spline::ExtractionModel& m) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (int e = 0; e < static_cast<int>(m.elements.size()); ++e)
    for (int k = 0; k < 27; ++k) {
      const Eigen::Vector3d x = spline::evaluate_element(m, e, Eigen::Vector3d(k % 3, (k / 3) % 3, k / 9) / 2.0);
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
    }
  return m.elements.empty() ? 0.0 : (hi - lo).norm();
}

std::vector<SurfaceFidelity> fidelity(const spline::ExtractionModel& m, const std::vector<mesh::TriMesh>& surfaces,
                                      double diagonal, const FidelityOptions& options) {
  if (!(diagonal > 0.0)) diagonal = model_diagonal(m);
  if (!(diagonal > 0.0)) throw bad_input("fidelity: the model has no extent");
  return fidelity_of([&](int s) { return detail::faces_of_surface(m, s); }, m.labels, surfaces, diagonal, options);
}

}  // namespace igaprep::iga_check
