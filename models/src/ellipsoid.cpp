#include <map>
#include <utility>

#include "igaprep/models/shapes.h"

namespace igaprep::models {

namespace {
// Index of the midpoint of edge (a, b), created on first use.
int midpoint(std::vector<Eigen::Vector3d>& points, std::map<std::pair<int, int>, int>& cache, int a, int b) {
  const auto key = std::minmax(a, b);
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  points.push_back((0.5 * (points[a] + points[b])).normalized());
  const int index = static_cast<int>(points.size()) - 1;
  cache.emplace(key, index);
  return index;
}
}  // namespace

mesh::TriMesh make_ellipsoid(double a, double b, double c, int levels) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> points = {{-1, t, 0}, {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                                         {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (auto& p : points) p.normalize();
  std::vector<Eigen::Vector3i> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                        {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                        {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                        {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> cache;
    std::vector<Eigen::Vector3i> finer;
    finer.reserve(faces.size() * 4);
    for (const auto& f : faces) {
      const int ab = midpoint(points, cache, f[0], f[1]);
      const int bc = midpoint(points, cache, f[1], f[2]);
      const int ca = midpoint(points, cache, f[2], f[0]);
      finer.push_back({f[0], ab, ca});
      finer.push_back({f[1], bc, ab});
      finer.push_back({f[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    faces.swap(finer);
  }
  mesh::TriMesh m;
  m.V.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (std::size_t i = 0; i < points.size(); ++i)
    m.V.row(static_cast<Eigen::Index>(i)) << a * points[i].x(), b * points[i].y(), c * points[i].z();
  m.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t i = 0; i < faces.size(); ++i) m.F.row(static_cast<Eigen::Index>(i)) = faces[i].transpose();
  return m;
}

}  // namespace igaprep::models
