#include "igaprep/spline/knot_families.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "igaprep/core/union_find.h"

namespace igaprep::spline {

namespace {

int node(int patch, int direction) { return 3 * patch + direction; }

bool same_parameters(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::abs(a[i] - b[i]) > 1e-10) return false;
  return true;
}

bool symmetric(const std::vector<double>& t) {
  const std::size_t m = t.size();
  for (std::size_t i = 0; i < m; ++i)
    if (std::abs(t[i] + t[m - 1 - i] - 1.0) > 1e-10) return false;
  return true;
}

bool is_consistent(const MultiPatch& mp, const KnotFamily& f) {
  const FamilyMember& first = f.members.front();
  const Patch& p0 = mp.patches[static_cast<std::size_t>(first.patch)];
  const std::vector<double> reference = family_parameters(p0, first.direction, false);
  if (f.self_reversed && !symmetric(reference)) return false;
  for (const FamilyMember& m : f.members) {
    const Patch& p = mp.patches[static_cast<std::size_t>(m.patch)];
    if (p.degrees[m.direction] != p0.degrees[first.direction]) return false;
    if (!same_parameters(family_parameters(p, m.direction, m.reversed), reference)) return false;
  }
  return true;
}

}  // namespace

std::vector<double> family_parameters(const Patch& p, int direction, bool reversed) {
  const std::vector<double>& U = p.knots[static_cast<std::size_t>(direction)];
  const int deg = p.degrees[direction];
  const int n = p.count(direction);
  const double a = U[static_cast<std::size_t>(deg)], b = U[static_cast<std::size_t>(n)];
  std::vector<double> t;
  for (int i = deg + 1; i < n; ++i) {
    const double s = (U[static_cast<std::size_t>(i)] - a) / (b - a);
    t.push_back(reversed ? 1.0 - s : s);
  }
  std::sort(t.begin(), t.end());
  return t;
}

std::vector<KnotFamily> knot_families(const MultiPatch& mp) {
  const int nodes = 3 * static_cast<int>(mp.patches.size());
  UnionFind sets(nodes);
  std::vector<int> twisted;  // nodes tied to themselves reversed
  for (const Interface& itf : mp.interfaces)
    for (int d : itf.side_a.tangent_directions()) {
      const int relation = itf.orient[static_cast<std::size_t>(d)] ? 1 : -1;
      if (!sets.unite(node(itf.patch_a, d), node(itf.patch_b, itf.dirmap[static_cast<std::size_t>(d)]), relation))
        twisted.push_back(node(itf.patch_a, d));
    }
  std::map<int, std::size_t> family_of_root;
  std::vector<KnotFamily> families;
  for (int n = 0; n < nodes; ++n) {
    const auto [root, parity] = sets.find_with_parity(n);
    auto [it, added] = family_of_root.emplace(root, families.size());
    if (added) families.emplace_back();
    // The root is the smallest node, so the first member is the root itself.
    families[it->second].members.push_back({n / 3, n % 3, parity < 0});
  }
  for (int n : twisted) families[family_of_root.at(sets.find(n))].self_reversed = true;
  for (KnotFamily& f : families) f.consistent = is_consistent(mp, f);
  return families;
}

}  // namespace igaprep::spline
