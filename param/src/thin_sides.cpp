#include "igaprep/param/thin_sides.h"

#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

#include "igaprep/core/error.h"
#include "igaprep/mesh/principal_axes.h"
#include "face_graph.h"

namespace igaprep::param {
namespace {

using detail::FaceEdge;
using detail::FaceGeometry;
using detail::PlatePair;

using Triplets = std::vector<Eigen::Triplet<double>>;

// The graph Laplacian of those weights.
void add_neighbour_terms(const FaceGeometry& g, const std::vector<FaceEdge>& edges, double sharpness, Triplets& t) {
  for (const FaceEdge& e : edges) {
    const double w = detail::neighbour_weight(g, e, sharpness);
    t.emplace_back(e.a, e.a, w);
    t.emplace_back(e.b, e.b, w);
    t.emplace_back(e.a, e.b, -w);
    t.emplace_back(e.b, e.a, -w);
  }
}

// A plate pair wants opposite values: (x_f + x_g)^2 weighted by area / d^2.
void add_pair_terms(const FaceGeometry& g, const std::vector<PlatePair>& pairs, double max_distance, Triplets& t,
                    int& used) {
  for (const PlatePair& p : pairs) {
    if (p.distance > max_distance) continue;
    const double w = g.area(p.face) / (p.distance * p.distance);
    t.emplace_back(p.face, p.face, w);
    t.emplace_back(p.opposite, p.opposite, w);
    t.emplace_back(p.face, p.opposite, w);
    t.emplace_back(p.opposite, p.face, w);
    ++used;
  }
}

std::vector<char> paired_faces(Eigen::Index faces, const std::vector<PlatePair>& pairs, double max_distance) {
  std::vector<char> paired(static_cast<std::size_t>(faces), 0);
  for (const PlatePair& p : pairs)
    if (p.distance <= max_distance) paired[static_cast<std::size_t>(p.face)] = paired[static_cast<std::size_t>(p.opposite)] = 1;
  return paired;
}

// The area-weighted mean height along U of the paired faces: the height of
// the plates' midsurface when the plates are roughly flat.
double plate_mid_height(const FaceGeometry& g, const std::vector<char>& paired, const Eigen::Vector3d& up) {
  double sum = 0.0, area = 0.0;
  for (std::size_t f = 0; f < paired.size(); ++f)
    if (paired[f]) {
      sum += g.area(static_cast<Eigen::Index>(f)) * up.dot(g.centroid.row(static_cast<Eigen::Index>(f)).transpose());
      area += g.area(static_cast<Eigen::Index>(f));
    }
  return area > 0.0 ? sum / area : 0.0;
}

// Faces in no plate pair (a thick hub's walls) get their side again: the
// paired faces fixed at +-1 by the first solve's sign, the others smooth
// between them and pulled (as strongly as by their neighbours) towards the
// side of the plates' mid-height they lie on, or their normal's side along U
// where that is clearer. In the first solve such faces only follow the plates
// around them, and a hub's wall went wholly to the side of the blade
// surfaces that meet it, the loop running along its top edge.
Eigen::VectorXd settle_thick_parts(const FaceGeometry& g, const std::vector<FaceEdge>& edges,
                                   const std::vector<char>& paired, const Eigen::Vector3d& up, double thickness,
                                   double sharpness, const Eigen::VectorXd& first) {
  const Eigen::Index nf = first.size();
  std::vector<int> free_index(static_cast<std::size_t>(nf), -1);
  int nfree = 0;
  for (Eigen::Index f = 0; f < nf; ++f)
    if (!paired[static_cast<std::size_t>(f)]) free_index[static_cast<std::size_t>(f)] = nfree++;
  Eigen::VectorXd x = first.cwiseSign();
  if (nfree == 0) return x;
  const double mid = plate_mid_height(g, paired, up);
  Triplets t;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(nfree), degree = Eigen::VectorXd::Zero(nfree);
  for (const FaceEdge& e : edges) {
    const double w = detail::neighbour_weight(g, e, sharpness);
    const int ia = free_index[static_cast<std::size_t>(e.a)], ib = free_index[static_cast<std::size_t>(e.b)];
    for (const auto& [i, j, other] : {std::tuple{ia, ib, e.b}, std::tuple{ib, ia, e.a}}) {
      if (i < 0) continue;
      t.emplace_back(i, i, w);
      degree(i) += w;
      if (j >= 0) t.emplace_back(i, j, -w);
      else rhs(i) += w * x(other);
    }
  }
  for (Eigen::Index f = 0; f < nf; ++f) {
    const int i = free_index[static_cast<std::size_t>(f)];
    if (i < 0) continue;
    const double height = (up.dot(g.centroid.row(f).transpose()) - mid) / (0.5 * thickness);
    const double prior = std::clamp(g.normal.row(f).dot(up) + std::clamp(height, -1.0, 1.0), -1.0, 1.0);
    const double lambda = std::max(degree(i), 1e-12);
    t.emplace_back(i, i, lambda);
    rhs(i) += lambda * prior;
  }
  Eigen::SparseMatrix<double> A(nfree, nfree);
  A.setFromTriplets(t.begin(), t.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
  if (solver.info() != Eigen::Success) throw internal_error("thin sides: the thick parts' matrix is singular");
  const Eigen::VectorXd y = solver.solve(rhs);
  for (Eigen::Index f = 0; f < nf; ++f) {
    const int i = free_index[static_cast<std::size_t>(f)];
    if (i >= 0) x(f) = y(i);
  }
  return x;
}

}  // namespace

ThinSides thin_sides(const mesh::TriMesh& T1, const ThinSidesOptions& o) {
  const FaceGeometry g = detail::face_geometry(T1);
  const std::vector<PlatePair> pairs = detail::plate_pairs(T1, g);
  if (pairs.empty()) throw bad_input("thin sides: no face of the surface faces another across the solid");
  ThinSides r;
  r.median_thickness = detail::median_distance(pairs);
  r.up = mesh::surface_principal_axes(T1).axes.col(0);

  const std::vector<FaceEdge> edges = detail::face_neighbours(T1);
  Triplets t;
  add_neighbour_terms(g, edges, o.sharpness, t);
  const double max_distance = o.thin_factor * r.median_thickness;
  add_pair_terms(g, pairs, max_distance, t, r.plate_pairs);
  // The pull: a small multiple of the area on the diagonal, and n . U on the right.
  const Eigen::Index nf = T1.F.rows();
  const double scale = g.area.mean() / (r.median_thickness * r.median_thickness);
  Eigen::VectorXd rhs(nf);
  for (Eigen::Index f = 0; f < nf; ++f) {
    t.emplace_back(f, f, o.pull * scale * g.area(f) / g.area.mean());
    rhs(f) = g.area(f) * g.normal.row(f).dot(r.up);
  }
  Eigen::SparseMatrix<double> A(nf, nf);
  A.setFromTriplets(t.begin(), t.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
  if (solver.info() != Eigen::Success) throw internal_error("thin sides: the side field's matrix is singular");
  r.face_value = solver.solve(rhs);
  const std::vector<char> paired = paired_faces(nf, pairs, max_distance);
  r.face_value = settle_thick_parts(g, edges, paired, r.up, r.median_thickness, o.sharpness, r.face_value);
  r.flipped_pieces = detail::give_small_pieces_away(edges, g.area, r.face_value);
  r.vertex_value = detail::vertex_means(T1, g.area, r.face_value);
  return r;
}

}  // namespace igaprep::param
