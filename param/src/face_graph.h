#pragma once
// A triangle mesh's faces as a graph: their geometry, the pairs sharing an
// edge, and sign fields on them (the thin sides of a solid, the sides of its
// tunnel loops).
#include <vector>

#include <Eigen/Core>

#include "igaprep/mesh/tri_mesh.h"

namespace igaprep::param::detail {

struct FaceGeometry {
  Eigen::MatrixXd normal, centroid;  // #F x 3
  Eigen::VectorXd area;
};
FaceGeometry face_geometry(const mesh::TriMesh& m);

// Pairs of faces sharing an edge (u, v), with the edge's length.
struct FaceEdge {
  int a, b;
  double length;
  int u = -1, v = -1;
};
std::vector<FaceEdge> face_neighbours(const mesh::TriMesh& m);

// Neighbours want equal values, weakly across sharp edges (where a rim loop
// should run): exp(-(1 - cos)/sharpness) times the cotangent-like ratio of
// the shared edge's length to the centroids' spacing. 0 for coincident centroids.
double neighbour_weight(const FaceGeometry& g, const FaceEdge& e, double sharpness);

// Every connected piece of each sign but the largest (by area) changes sign.
// Returns how many pieces changed.
int give_small_pieces_away(const std::vector<FaceEdge>& edges, const Eigen::VectorXd& area, Eigen::VectorXd& x);

// A face and the face its inward ray meets first when that one faces back
// (normals more than 120 degrees apart): the two sides of a thin part.
struct PlatePair {
  int face, opposite;
  double distance;
};
std::vector<PlatePair> plate_pairs(const mesh::TriMesh& m, const FaceGeometry& g);
double median_distance(std::vector<PlatePair> pairs);  // of a non-empty list

// Per vertex the area-weighted mean of its faces' values.
Eigen::VectorXd vertex_means(const mesh::TriMesh& m, const Eigen::VectorXd& area, const Eigen::VectorXd& x);

}  // namespace igaprep::param::detail
