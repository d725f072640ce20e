#pragma once
// Fidelity of a model to its input surfaces: how far the spline faces that
// stand for an input surface (boundary sides labelled with it, material
// interfaces lying on it) are from that triangle mesh, measured both ways:
//  - spline -> mesh: samples of the spline faces (a regular grid per face
//    element) to the triangle mesh, exact point-triangle distances (CGAL AABB tree);
//  - mesh -> spline: every mesh vertex to the spline faces: the nearest point
//    of a fine tessellation of the faces (CGAL AABB tree) refined by a
//    Gauss-Newton projection onto the spline face itself.
// Surface i of the list is the model's label i (label 0 = outer surface T1,
// ARCHITECTURE.md), so surfaces are given outermost first.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "igaprep/mesh/tri_mesh.h"
#include "igaprep/spline/extraction_model.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::iga_check {

struct FidelityOptions {
  int samples_per_element = 9;       // per direction, per face element (ends included)
  int tessellation_per_element = 8;  // quads per direction, per face element
  int newton_iterations = 20;
  int only_surface = -1;  // >= 0: measure that surface alone (the others' meshes may be empty)
};

struct DistanceStats {
  long samples = 0;
  double max = 0.0, mean = 0.0, p95 = 0.0;                    // model units
  double max_relative = 0.0, mean_relative = 0.0, p95_relative = 0.0;  // / bounding-box diagonal
  Eigen::Vector3d max_location = Eigen::Vector3d::Zero();    // the sample farthest away
};

// One spline face standing for a surface: its farthest sample from the mesh.
struct FaceDistance {
  int patch = -1;
  int element = -1;  // of an extraction model (its patch in `patch`); -1 for a multipatch
  spline::Side side;
  bool interface = false;  // a material interface (else a labelled boundary side)
  double max = 0.0;        // model units
  Eigen::Vector3d max_location = Eigen::Vector3d::Zero();
};

struct SurfaceFidelity {
  int surface = -1;                  // index into the surface list = model label
  std::string label;                 // the model's label name ("" when absent)
  int boundary_faces = 0, interface_faces = 0;  // spline faces that stand for it
  DistanceStats spline_to_mesh, mesh_to_spline;
  std::vector<FaceDistance> faces;     // spline -> mesh, per face, in the order of the statistics
  std::vector<double> vertex_distance;  // mesh -> spline, per mesh vertex (model units)
};

// A part of an input surface the model does not cover: mesh vertices farther
// than a limit from the spline faces, connected through mesh edges.
struct UncoveredRegion {
  int vertices = 0;
  double max = 0.0;  // distance of its farthest vertex (model units)
  Eigen::Vector3d farthest = Eigen::Vector3d::Zero(), centroid = Eigen::Vector3d::Zero();
};

// The regions of `mesh` whose vertex `distance` exceeds `limit`, farthest first.
std::vector<UncoveredRegion> uncovered_regions(const mesh::TriMesh& mesh, const std::vector<double>& distance,
                                               double limit);

// Diagonal of the bounding box of the model's points (evaluated on a 3^3 grid
// per element, so curved patches are not judged by their control hull).
double model_diagonal(const spline::MultiPatch& mp);

// The same for a model in extraction form (a T-spline): 3^3 points per element.
double model_diagonal(const spline::ExtractionModel& m);

// Diagonal of the bounding box of a mesh's vertices.
double mesh_diagonal(const mesh::TriMesh& m);

// Inputs: model, input surfaces (outermost first, index = label), the length
// that relative distances divide by (model_diagonal when <= 0).
// Output: one entry per surface that at least one spline face stands for.
std::vector<SurfaceFidelity> fidelity(const spline::MultiPatch& mp, const std::vector<mesh::TriMesh>& surfaces,
                                      double diagonal = 0.0, const FidelityOptions& options = {});

// The same for a model in extraction form (a T-spline): its boundary faces
// and interface faces, each element face sampled as a face element.
std::vector<SurfaceFidelity> fidelity(const spline::ExtractionModel& m, const std::vector<mesh::TriMesh>& surfaces,
                                      double diagonal = 0.0, const FidelityOptions& options = {});

}  // namespace igaprep::iga_check
