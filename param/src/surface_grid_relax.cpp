#include "igaprep/param/surface_grid_relax.h"

#include <algorithm>
#include <array>
#include <cstddef>

#include <Eigen/Geometry>

namespace igaprep::param {

namespace {

struct GridOnSurface {
  int m;
  std::vector<Eigen::Vector3d> x;
  std::vector<Eigen::Vector3d> normal;  // the surface's at each point

  std::size_t at(int i, int j) const { return static_cast<std::size_t>(i + m * j); }

  // The four corners' turns of cell (i, j) against the surface normal,
  // counter-clockwise from (i, j): positive where the cell keeps the
  // grid's orientation (times orient).
  bool folded(int i, int j, double orient) const {
    const std::array<std::size_t, 4> c{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
    for (int k = 0; k < 4; ++k) {
      const std::size_t cur = c[static_cast<std::size_t>(k)], next = c[static_cast<std::size_t>((k + 1) % 4)],
                        prev = c[static_cast<std::size_t>((k + 3) % 4)];
      if (orient * (x[next] - x[cur]).cross(x[prev] - x[cur]).dot(normal[cur]) <= 0.0) return true;
    }
    return false;
  }

  double orientation() const {
    double sum = 0.0;
    for (int j = 0; j + 1 < m; ++j)
      for (int i = 0; i + 1 < m; ++i) {
        const Eigen::Vector3d a = x[at(i, j)], b = x[at(i + 1, j)], d = x[at(i, j + 1)];
        sum += (b - a).cross(d - a).dot(normal[at(i, j)]) > 0.0 ? 1.0 : -1.0;
      }
    return sum >= 0.0 ? 1.0 : -1.0;
  }

  int count_folded(double orient) const {
    int n = 0;
    for (int j = 0; j + 1 < m; ++j)
      for (int i = 0; i + 1 < m; ++i) n += folded(i, j, orient) ? 1 : 0;
    return n;
  }

  // The folded flags of the (up to four) cells around point (i, j).
  std::array<bool, 4> cells_around(int i, int j, double orient) const {
    std::array<bool, 4> f{};
    int k = 0;
    for (int dj = -1; dj <= 0; ++dj)
      for (int di = -1; di <= 0; ++di, ++k) {
        const int ci = i + di, cj = j + dj;
        if (ci >= 0 && cj >= 0 && ci + 1 < m && cj + 1 < m) f[static_cast<std::size_t>(k)] = folded(ci, cj, orient);
      }
    return f;
  }
};

GridOnSurface on_surface(const std::vector<Eigen::Vector3d>& grid, int m, const SurfaceProjector& surface) {
  GridOnSurface g{m, grid, {}};
  g.normal.reserve(grid.size());
  for (const Eigen::Vector3d& p : grid) {
    int tri = -1;
    surface.closest(p, &tri);
    g.normal.push_back(surface.normal(tri));
  }
  return g;
}

double grid_size(const std::vector<Eigen::Vector3d>& grid) {
  Eigen::Vector3d lo = grid.front(), hi = grid.front();
  for (const Eigen::Vector3d& p : grid) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

// Moves point (i, j) to the surface point nearest its neighbours' mean
// unless that folds a cell around it or lands on a part facing away;
// returns how far it moved.
double relax_point(GridOnSurface& g, int i, int j, double orient, const SurfaceProjector& surface,
                   const SurfaceGridRelaxOptions& options) {
  const std::size_t p = g.at(i, j);
  const Eigen::Vector3d mean = 0.25 * (g.x[g.at(i - 1, j)] + g.x[g.at(i + 1, j)] + g.x[g.at(i, j - 1)] + g.x[g.at(i, j + 1)]);
  int tri = -1;
  const Eigen::Vector3d to = surface.closest(mean, &tri);
  const Eigen::Vector3d n = surface.normal(tri);
  if (n.dot(g.normal[p]) < options.min_normal_cosine) return 0.0;
  const std::array<bool, 4> before = g.cells_around(i, j, orient);
  const Eigen::Vector3d old_x = g.x[p], old_n = g.normal[p];
  g.x[p] = to;
  g.normal[p] = n;
  const std::array<bool, 4> after = g.cells_around(i, j, orient);
  for (std::size_t k = 0; k < 4; ++k)
    if (after[k] && !before[k]) {
      g.x[p] = old_x;
      g.normal[p] = old_n;
      return 0.0;
    }
  return (to - old_x).norm();
}

// The points of folded cells and of `rings` rings of cells around them.
std::vector<char> near_folds(const GridOnSurface& g, double orient, int rings) {
  const int m = g.m;
  std::vector<char> in(static_cast<std::size_t>(m * m), 0);
  for (int j = 0; j + 1 < m; ++j)
    for (int i = 0; i + 1 < m; ++i)
      if (g.folded(i, j, orient))
        for (int dj = -rings; dj <= rings + 1; ++dj)
          for (int di = -rings; di <= rings + 1; ++di) {
            const int pi = i + di, pj = j + dj;
            if (pi >= 0 && pj >= 0 && pi < m && pj < m) in[g.at(pi, pj)] = 1;
          }
  return in;
}

}  // namespace

int count_folded_on_surface(const std::vector<Eigen::Vector3d>& grid, int m, const SurfaceProjector& surface) {
  const GridOnSurface g = on_surface(grid, m, surface);
  return g.count_folded(g.orientation());
}

SurfaceGridRelaxResult relax_grid_on_surface(const std::vector<Eigen::Vector3d>& grid, int m,
                                            const SurfaceProjector& surface, const SurfaceGridRelaxOptions& options) {
  GridOnSurface g = on_surface(grid, m, surface);
  const double orient = g.orientation();
  SurfaceGridRelaxResult out;
  out.folded_before = g.count_folded(orient);
  const double tolerance = 1e-6 * grid_size(grid);
  std::vector<char> movable = options.rings < 0 ? std::vector<char>(grid.size(), 1) : near_folds(g, orient, options.rings);
  for (int round = 0; round < options.rounds; ++round) {
    double largest = 0.0;
    for (int j = 1; j + 1 < m; ++j)
      for (int i = 1; i + 1 < m; ++i)
        if (movable[g.at(i, j)]) largest = std::max(largest, relax_point(g, i, j, orient, surface, options));
    if (largest <= tolerance) break;
  }
  out.folded_after = g.count_folded(orient);
  out.grid = std::move(g.x);
  return out;
}

}  // namespace igaprep::param
