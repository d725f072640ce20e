#include "igaprep/spline/submodel.h"

#include <algorithm>
#include <array>
#include <deque>
#include <map>
#include <set>

#include "igaprep/core/error.h"

namespace igaprep::spline {

namespace {

// Old patch index -> new index (the position in `patches`); throws on a bad
// or repeated index.
std::map<int, int> renumber(const MultiPatch& mp, const std::vector<int>& patches) {
  std::map<int, int> new_index;
  for (int p : patches) {
    if (p < 0 || p >= static_cast<int>(mp.patches.size()) || new_index.count(p))
      throw internal_error("submodel: bad or repeated patch index " + std::to_string(p));
    const int next = static_cast<int>(new_index.size());
    new_index[p] = next;
  }
  return new_index;
}

// The kept patches in their new order, without solutions.
std::vector<Patch> kept_patches(const MultiPatch& mp, const std::map<int, int>& new_index) {
  std::vector<Patch> patches(new_index.size());
  for (const auto& [old, now] : new_index) {
    patches[now] = mp.patches[old];
    patches[now].displacement.resize(0, 0);
  }
  return patches;
}

// Per new patch, by Side::array_index(): whether an interface or a boundary
// of the submodel holds the side.
using CoveredSides = std::vector<std::array<bool, 6>>;

void cover(CoveredSides& covered, int patch, Side side) { covered[patch][side.array_index()] = true; }

// The interfaces between two kept patches, renumbered.
void keep_interfaces(const MultiPatch& mp, const std::map<int, int>& new_index, MultiPatch& sub,
                     CoveredSides& covered) {
  for (const auto& itf : mp.interfaces) {
    auto a = new_index.find(itf.patch_a), b = new_index.find(itf.patch_b);
    if (a == new_index.end() || b == new_index.end()) continue;
    Interface i = itf;
    i.patch_a = a->second;
    i.patch_b = b->second;
    sub.interfaces.push_back(i);
    cover(covered, i.patch_a, i.side_a);
    cover(covered, i.patch_b, i.side_b);
  }
}

// The labelled sides of kept patches, renumbered.
void keep_boundaries(const MultiPatch& mp, const std::map<int, int>& new_index, MultiPatch& sub,
                     CoveredSides& covered) {
  for (const auto& bs : mp.boundaries) {
    auto a = new_index.find(bs.patch);
    if (a == new_index.end()) continue;
    BoundarySide s = bs;
    s.patch = a->second;
    sub.boundaries.push_back(s);
    cover(covered, s.patch, s.side);
  }
}

// Every side not covered becomes a boundary labelled `cut_label`, which is
// added to the labels when first used.
void label_cuts(const CoveredSides& covered, const std::string& cut_label, MultiPatch& sub) {
  int cut = -1;
  for (int p = 0; p < static_cast<int>(sub.patches.size()); ++p)
    for (const Side side : Side::all()) {
      if (covered[p][side.array_index()]) continue;
      if (cut < 0) {
        cut = static_cast<int>(sub.labels.size());
        sub.labels.push_back(cut_label);
      }
      sub.boundaries.push_back({p, side, cut});
    }
}

}  // namespace

MultiPatch submodel(const MultiPatch& mp, const std::vector<int>& patches, const std::string& cut_label) {
  const std::map<int, int> new_index = renumber(mp, patches);
  MultiPatch sub;
  sub.labels = mp.labels;
  sub.materials = mp.materials;
  sub.patches = kept_patches(mp, new_index);
  CoveredSides covered(sub.patches.size(), std::array<bool, 6>{});
  keep_interfaces(mp, new_index, sub, covered);
  keep_boundaries(mp, new_index, sub, covered);
  label_cuts(covered, cut_label, sub);
  return sub;
}

std::vector<int> connected_patches(const MultiPatch& mp, const std::vector<bool>& eligible,
                                    const std::vector<double>& score, int max_patches) {
  const int n = static_cast<int>(mp.patches.size());
  int start = -1;
  for (int p = 0; p < n; ++p)
    if (eligible[p] && (start < 0 || score[p] < score[start])) start = p;
  if (start < 0) return {};
  if (max_patches <= 0 || max_patches >= n) {
    std::vector<int> all;
    for (int p = 0; p < n; ++p)
      if (eligible[p]) all.push_back(p);
    return all;
  }
  std::vector<std::set<int>> neighbours(n);
  for (const auto& itf : mp.interfaces) {
    neighbours[itf.patch_a].insert(itf.patch_b);
    neighbours[itf.patch_b].insert(itf.patch_a);
  }
  std::vector<int> chosen{start};
  std::set<int> seen{start};
  std::deque<int> queue{start};
  while (!queue.empty() && static_cast<int>(chosen.size()) < max_patches) {
    const int p = queue.front();
    queue.pop_front();
    for (int q : neighbours[p]) {
      if (static_cast<int>(chosen.size()) >= max_patches) break;
      if (!eligible[q] || seen.count(q)) continue;
      seen.insert(q);
      chosen.push_back(q);
      queue.push_back(q);
    }
  }
  std::sort(chosen.begin(), chosen.end());
  return chosen;
}

}  // namespace igaprep::spline
