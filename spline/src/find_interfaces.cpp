#include "igaprep/spline/find_interfaces.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <vector>

#include "igaprep/core/error.h"
#include "igaprep/core/union_find.h"
#include "igaprep/spline/curve_surface.h"
#include "igaprep/spline/multipatch_topology.h"

namespace igaprep::spline {

namespace {

struct PointRef {
  int patch, index;
};

}  // namespace

int stitch_control_points(MultiPatch& mp, double tol, double* max_move) {
  if (!(tol > 0.0)) throw bad_input("stitch_control_points: tolerance must be positive");
  // Side control points of every patch, each once.
  std::vector<PointRef> refs;
  for (int p = 0; p < static_cast<int>(mp.patches.size()); ++p) {
    std::vector<int> idx;
    for (const Side s : Side::all()) {
      const auto side = side_control_points(mp.patches[p], s);
      idx.insert(idx.end(), side.begin(), side.end());
    }
    std::sort(idx.begin(), idx.end());
    idx.erase(std::unique(idx.begin(), idx.end()), idx.end());
    for (int i : idx) refs.push_back({p, i});
  }
  auto point = [&](const PointRef& r) -> Eigen::Vector3d {
    return mp.patches[r.patch].control_points.row(r.index).transpose();
  };
  // Hash grid with cells of size tol: close points are in neighbouring cells.
  using Key = std::tuple<long long, long long, long long>;
  std::map<Key, std::vector<int>> cells;
  auto key = [&](const Eigen::Vector3d& x) {
    return Key{static_cast<long long>(std::floor(x.x() / tol)), static_cast<long long>(std::floor(x.y() / tol)),
               static_cast<long long>(std::floor(x.z() / tol))};
  };
  for (int i = 0; i < static_cast<int>(refs.size()); ++i) cells[key(point(refs[i]))].push_back(i);
  UnionFind close(static_cast<int>(refs.size()));  // the root, the smallest index, is where a set moves to
  for (int i = 0; i < static_cast<int>(refs.size()); ++i) {
    const Eigen::Vector3d x = point(refs[i]);
    const auto [kx, ky, kz] = key(x);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          const auto it = cells.find(Key{kx + dx, ky + dy, kz + dz});
          if (it == cells.end()) continue;
          for (int j : it->second)
            if (j > i && (point(refs[j]) - x).norm() <= tol) close.unite(i, j);
        }
  }
  int moved = 0;
  double largest = 0.0;
  for (int i = 0; i < static_cast<int>(refs.size()); ++i) {
    const int r = close.find(i);
    if (r == i) continue;
    const Eigen::Vector3d target = point(refs[r]);
    const double d = (point(refs[i]) - target).norm();
    if (d > 0.0) {
      ++moved;
      largest = std::max(largest, d);
      mp.patches[refs[i].patch].control_points.row(refs[i].index) = target.transpose();
    }
  }
  if (max_move) *max_move = largest;
  return moved;
}

void find_interfaces(MultiPatch& mp, double tol) {
  mp.interfaces.clear();
  const int np = static_cast<int>(mp.patches.size());
  // Side centroids first: only sides with the same centroid can match.
  std::vector<std::array<Eigen::Vector3d, 6>> centroid(static_cast<std::size_t>(np));
  std::vector<std::array<int, 6>> count(static_cast<std::size_t>(np));
  for (int p = 0; p < np; ++p)
    for (const Side s : Side::all()) {
      const auto idx = side_control_points(mp.patches[p], s);
      Eigen::Vector3d c = Eigen::Vector3d::Zero();
      for (int i : idx) c += mp.patches[p].control_points.row(i).transpose();
      centroid[p][s.array_index()] = c / static_cast<double>(idx.size());
      count[p][s.array_index()] = static_cast<int>(idx.size());
    }
  std::vector<std::array<bool, 6>> used(static_cast<std::size_t>(np), std::array<bool, 6>{});
  for (int a = 0; a < np; ++a)
    for (const Side sa : Side::all()) {
      const int ia = sa.array_index();
      if (used[a][ia]) continue;
      for (int b = a + 1; b < np && !used[a][ia]; ++b)
        for (const Side sb : Side::all()) {
          const int ib = sb.array_index();
          if (used[a][ia]) break;
          if (used[b][ib] || count[a][ia] != count[b][ib]) continue;
          if ((centroid[a][ia] - centroid[b][ib]).norm() > tol) continue;
          const int da = sa.direction(), db = sb.direction();
          const auto ta = sa.tangent_directions(), tb = sb.tangent_directions();
          MultiPatch probe;
          probe.patches = {mp.patches[a], mp.patches[b]};
          for (int swap = 0; swap < 2 && !used[a][ia]; ++swap)
            for (int o = 0; o < 4 && !used[a][ia]; ++o) {
              Interface itf;
              itf.patch_a = 0;
              itf.side_a = sa;
              itf.patch_b = 1;
              itf.side_b = sb;
              itf.dirmap[da] = db;
              itf.orient[da] = sa.parameter() != sb.parameter() ? 1 : 0;
              itf.dirmap[ta[0]] = tb[swap];
              itf.dirmap[ta[1]] = tb[1 - swap];
              itf.orient[ta[0]] = o & 1;
              itf.orient[ta[1]] = (o >> 1) & 1;
              probe.interfaces = {itf};
              try {
                if (!check_conformity(probe, tol).conforming) continue;
              } catch (const Error&) {
                continue;  // counts do not match under this direction map
              }
              itf.patch_a = a;
              itf.patch_b = b;
              mp.interfaces.push_back(itf);
              used[a][ia] = used[b][ib] = true;
            }
        }
    }
}

}  // namespace igaprep::spline
