#include "igaprep/param/lid_relax.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cstddef>

namespace igaprep::param {

namespace {

using Grid = std::vector<Eigen::Vector3d>;

// The corner volumes of cell (i, j) at heights 0, 1/2 and 1 of the ruled
// block, each corner with its own column lid - base.
bool cell_folded(const Grid& base, const Grid& lid, int m, int i, int j) {
  auto at = [m](int a, int b) { return static_cast<std::size_t>(a + m * b); };
  const std::array<std::size_t, 4> c{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
  for (std::size_t k = 0; k < 4; ++k) {
    const std::size_t cur = c[k], next = c[(k + 1) % 4], prev = c[(k + 3) % 4];
    const Eigen::Vector3d column = lid[cur] - base[cur];
    auto turn = [&](double h) {
      auto x = [&](std::size_t q) { return Eigen::Vector3d((1.0 - h) * base[q] + h * lid[q]); };
      return (x(next) - x(cur)).cross(x(prev) - x(cur)).dot(column);
    };
    const double at_base = turn(0.0);
    if (at_base == 0.0) continue;  // a degenerate base cell is M's, not the lid's
    if (turn(0.5) * at_base <= 0.0 || turn(1.0) * at_base <= 0.0) return true;
  }
  return false;
}

// Segment a..b of a strip between base and lid turns back at the lid or
// halfway to it.
bool segment_folded(const Grid& base, const Grid& lid, std::size_t a, std::size_t b) {
  const Eigen::Vector3d tb = base[b] - base[a], tl = lid[b] - lid[a];
  return (0.5 * (tb + tl)).dot(tb) <= 0.0 || tl.dot(tb) <= 0.0;
}

// The lid point of base point p re-aimed at target; unchanged where the ray
// would turn to M's other side or fails.
void aim(const Grid& base, Grid& lid, std::size_t p, const Eigen::Vector3d& target, const LidRay& ray) {
  const Eigen::Vector3d dir = target - base[p];
  if (!(dir.norm() > 0.0) || dir.dot(lid[p] - base[p]) <= 0.0) return;
  if (const std::optional<Eigen::Vector3d> end = ray(base[p], dir.normalized())) lid[p] = *end;
}

// The folded cells in groups that touch (corners included), each a list of
// cell indices i + m j.
std::vector<std::vector<int>> folded_groups(const Grid& base, const Grid& lid, int m) {
  const int n = m - 1;
  std::vector<int> group(static_cast<std::size_t>(n * n), -1);
  std::vector<std::vector<int>> groups;
  for (int c0 = 0; c0 < n * n; ++c0) {
    if (group[static_cast<std::size_t>(c0)] >= 0 || !cell_folded(base, lid, m, c0 % n, c0 / n)) continue;
    groups.emplace_back();
    std::vector<int> stack{c0};
    group[static_cast<std::size_t>(c0)] = static_cast<int>(groups.size()) - 1;
    while (!stack.empty()) {
      const int c = stack.back();
      stack.pop_back();
      groups.back().push_back(c);
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const int i = c % n + di, j = c / n + dj;
          if (i < 0 || j < 0 || i >= n || j >= n) continue;
          const int d = i + n * j;
          if (group[static_cast<std::size_t>(d)] >= 0 || !cell_folded(base, lid, m, i, j)) continue;
          group[static_cast<std::size_t>(d)] = group[static_cast<std::size_t>(c)];
          stack.push_back(d);
        }
    }
  }
  return groups;
}

// The inner points of the given cells and of `rings` rings of cells around them.
std::vector<char> points_near(const std::vector<int>& cells, int m, int rings) {
  const int n = m - 1;
  std::vector<char> move(static_cast<std::size_t>(m * m), 0);
  for (int c : cells) {
    const int i = c % n, j = c / n;
    for (int pj = std::max(1, j - rings); pj <= std::min(m - 2, j + 1 + rings); ++pj)
      for (int pi = std::max(1, i - rings); pi <= std::min(m - 2, i + 1 + rings); ++pi)
        move[static_cast<std::size_t>(pi + m * pj)] = 1;
  }
  return move;
}

// The moving points placed where a discrete harmonic grid puts them (each the
// mean of its four neighbours, the others fixed), then their rays re-aimed there.
void aim_harmonic(const Grid& base, Grid& lid, int m, const std::vector<char>& move, const LidRay& ray) {
  Grid target = lid;
  auto at = [m](int i, int j) { return static_cast<std::size_t>(i + m * j); };
  for (int sweep = 0; sweep < 4 * m; ++sweep)
    for (int j = 1; j + 1 < m; ++j)
      for (int i = 1; i + 1 < m; ++i)
        if (move[at(i, j)])
          target[at(i, j)] = 0.25 * (target[at(i - 1, j)] + target[at(i + 1, j)] + target[at(i, j - 1)] + target[at(i, j + 1)]);
  for (std::size_t p = 0; p < move.size(); ++p)
    if (move[p]) aim(base, lid, p, target[p], ray);
}

}  // namespace

int count_folded_lid_cells(const Grid& base, const Grid& lid, int m) {
  int n = 0;
  for (int j = 0; j + 1 < m; ++j)
    for (int i = 0; i + 1 < m; ++i) n += cell_folded(base, lid, m, i, j) ? 1 : 0;
  return n;
}

// Each run of folded segments is replaced, between the nearest points
// around it that keep their order, by lid points spread along the chord
// between those two as the base points are along theirs.
void relax_lid_side(const Grid& base, Grid& lid, const std::vector<std::size_t>& at, const LidRay& ray) {
  const std::size_t n = at.size();
  auto folded_count = [&] {
    int c = 0;
    for (std::size_t k = 0; k + 1 < n; ++k) c += segment_folded(base, lid, at[k], at[k + 1]) ? 1 : 0;
    return c;
  };
  std::size_t k = 0;
  while (k + 1 < n) {
    if (!segment_folded(base, lid, at[k], at[k + 1])) {
      ++k;
      continue;
    }
    std::size_t a = k, b = k + 1;
    while (b + 1 < n && segment_folded(base, lid, at[b], at[b + 1])) ++b;
    const Grid before = lid;
    const int count_before = folded_count();
    for (;;) {
      if (!segment_folded(base, lid, at[a], at[b])) {
        double total = 0.0;
        for (std::size_t q = a; q < b; ++q) total += (base[at[q + 1]] - base[at[q]]).norm();
        double s = 0.0;
        for (std::size_t q = a + 1; q < b; ++q) {
          s += (base[at[q]] - base[at[q - 1]]).norm();
          aim(base, lid, at[q], lid[at[a]] + (s / total) * (lid[at[b]] - lid[at[a]]), ray);
        }
        if (folded_count() < count_before) break;
        lid = before;
      }
      if (a == 0 && b + 1 == n) break;
      if (a > 0) --a;
      if (b + 1 < n) ++b;
    }
    k = b;
  }
}

std::vector<std::size_t> lid_side_indices(int m, int side) {
  std::vector<std::size_t> idx;
  for (int k = 0; k < m; ++k) {
    const int i = side == 0 || side == 1 ? k : side == 2 ? 0 : m - 1;
    const int j = side == 2 || side == 3 ? k : side == 0 ? 0 : m - 1;
    idx.push_back(static_cast<std::size_t>(i + m * j));
  }
  return idx;
}

int relax_lid_inside(const Grid& base, Grid& lid, int m, const LidRay& ray, int max_rings) {
  int folded = count_folded_lid_cells(base, lid, m);
  for (const std::vector<int>& cells : folded_groups(base, lid, m))
    for (int rings = 1; folded > 0 && rings <= max_rings; rings *= 2) {
      const Grid before = lid;
      aim_harmonic(base, lid, m, points_near(cells, m, rings), ray);
      const int now = count_folded_lid_cells(base, lid, m);
      if (now < folded) folded = now;
      else lid = before;
    }
  return folded;
}

}  // namespace igaprep::param
