#include "face_graph.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "igaprep/core/edge_key.h"
#include "igaprep/core/union_find.h"
#include "igaprep/mesh/ray_caster.h"

namespace igaprep::param::detail {
namespace {

// Connected pieces of the faces of one sign (across shared edges).
std::vector<int> pieces_of_sign(const std::vector<FaceEdge>& edges, const Eigen::VectorXd& x, int sign) {
  UnionFind uf(static_cast<int>(x.size()));
  for (const FaceEdge& e : edges)
    if ((x(e.a) > 0) == (sign > 0) && (x(e.b) > 0) == (sign > 0)) uf.unite(e.a, e.b);
  std::vector<int> piece(static_cast<std::size_t>(x.size()));
  for (int f = 0; f < static_cast<int>(x.size()); ++f) piece[static_cast<std::size_t>(f)] = uf.find(f);
  return piece;
}

}  // namespace

FaceGeometry face_geometry(const mesh::TriMesh& m) {
  FaceGeometry g{Eigen::MatrixXd(m.F.rows(), 3), Eigen::MatrixXd(m.F.rows(), 3), Eigen::VectorXd(m.F.rows())};
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a);
    g.area(f) = 0.5 * n.norm();
    g.normal.row(f) = g.area(f) > 0.0 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::Zero();
    g.centroid.row(f) = (a + b + c) / 3.0;
  }
  return g;
}

std::vector<FaceEdge> face_neighbours(const mesh::TriMesh& m) {
  std::unordered_map<std::uint64_t, int> first;
  std::vector<FaceEdge> edges;
  for (int f = 0; f < static_cast<int>(m.F.rows()); ++f)
    for (int k = 0; k < 3; ++k) {
      const int u = m.F(f, k), v = m.F(f, (k + 1) % 3);
      const auto [it, inserted] = first.emplace(edge_key(u, v), f);
      if (!inserted) edges.push_back({it->second, f, (m.V.row(u) - m.V.row(v)).norm(), u, v});
    }
  return edges;
}

double neighbour_weight(const FaceGeometry& g, const FaceEdge& e, double sharpness) {
  const double cosine = g.normal.row(e.a).dot(g.normal.row(e.b));
  const double spacing = (g.centroid.row(e.a) - g.centroid.row(e.b)).norm();
  return spacing > 0.0 ? std::exp(-(1.0 - cosine) / sharpness) * e.length / spacing : 0.0;
}

int give_small_pieces_away(const std::vector<FaceEdge>& edges, const Eigen::VectorXd& area, Eigen::VectorXd& x) {
  int flipped = 0;
  for (int sign : {1, -1}) {
    const std::vector<int> piece = pieces_of_sign(edges, x, sign);
    std::unordered_map<int, double> piece_area;
    for (int f = 0; f < static_cast<int>(x.size()); ++f)
      if ((x(f) > 0) == (sign > 0)) piece_area[piece[static_cast<std::size_t>(f)]] += area(f);
    if (piece_area.size() < 2) continue;
    const int largest = std::max_element(piece_area.begin(), piece_area.end(),
                                         [](const auto& a, const auto& b) { return a.second < b.second; })
                            ->first;
    flipped += static_cast<int>(piece_area.size()) - 1;
    for (int f = 0; f < static_cast<int>(x.size()); ++f)
      if ((x(f) > 0) == (sign > 0) && piece[static_cast<std::size_t>(f)] != largest) x(f) = -x(f);
  }
  return flipped;
}

std::vector<PlatePair> plate_pairs(const mesh::TriMesh& m, const FaceGeometry& g) {
  const mesh::RayCaster caster(m);
  std::vector<PlatePair> pairs;
  for (int f = 0; f < static_cast<int>(m.F.rows()); ++f) {
    if (!(g.area(f) > 0.0)) continue;
    const Eigen::Vector3d n = g.normal.row(f);
    const auto hit = caster.first_hit(g.centroid.row(f).transpose(), -n, f);
    if (!hit || !(hit->distance > 0.0)) continue;
    if (g.normal.row(hit->face).dot(n) > -0.5) continue;
    pairs.push_back({f, hit->face, hit->distance});
  }
  return pairs;
}

double median_distance(std::vector<PlatePair> pairs) {
  const auto mid = pairs.begin() + static_cast<std::ptrdiff_t>(pairs.size() / 2);
  std::nth_element(pairs.begin(), mid, pairs.end(),
                   [](const PlatePair& a, const PlatePair& b) { return a.distance < b.distance; });
  return mid->distance;
}

Eigen::VectorXd vertex_means(const mesh::TriMesh& m, const Eigen::VectorXd& area, const Eigen::VectorXd& x) {
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(m.V.rows()), weight = Eigen::VectorXd::Zero(m.V.rows());
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      sum(m.F(f, k)) += area(f) * x(f);
      weight(m.F(f, k)) += area(f);
    }
  return sum.cwiseQuotient(weight.cwiseMax(1e-300));
}

}  // namespace igaprep::param::detail
