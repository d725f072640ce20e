#include "igaprep/spline/label_sides.h"

#include <algorithm>

#include "igaprep/core/error.h"

namespace igaprep::spline {

namespace {

// An interface between materials i-1 and i lies on surface i.
void label_interfaces(MultiPatch& mp) {
  for (auto& itf : mp.interfaces) {
    const int ma = mp.patches[itf.patch_a].material, mb = mp.patches[itf.patch_b].material;
    if (ma != mb) itf.surface = std::max(ma, mb);
  }
}

// Per patch, by Side::array_index(): whether the side is on an interface.
std::vector<std::array<bool, 6>> interface_sides(const MultiPatch& mp) {
  std::vector<std::array<bool, 6>> on_interface(mp.patches.size(), std::array<bool, 6>{});
  for (const auto& itf : mp.interfaces) {
    on_interface[itf.patch_a][itf.side_a.array_index()] = true;
    on_interface[itf.patch_b][itf.side_b.array_index()] = true;
  }
  return on_interface;
}

}  // namespace

int label_sides(MultiPatch& mp, const std::vector<std::array<int, 6>>& side_labels,
                const std::vector<std::array<bool, 6>>& collapsed) {
  if (side_labels.size() != mp.patches.size() || collapsed.size() != mp.patches.size())
    throw internal_error("label_sides: one entry per patch is needed");
  label_interfaces(mp);
  const std::vector<std::array<bool, 6>> on_interface = interface_sides(mp);
  int unmatched = 0;
  for (std::size_t p = 0; p < mp.patches.size(); ++p)
    for (const Side side : Side::all()) {
      const int s = side.array_index();
      if (on_interface[p][s]) continue;
      if (side_labels[p][s] >= 0) mp.boundaries.push_back({static_cast<int>(p), side, side_labels[p][s]});
      else if (!collapsed[p][s]) ++unmatched;
    }
  return unmatched;
}

int label_index(const MultiPatch& mp, const std::string& name) {
  for (size_t i = 0; i < mp.labels.size(); ++i)
    if (mp.labels[i] == name) return static_cast<int>(i);
  return -1;
}

std::string label_list(const MultiPatch& mp) {
  std::string s;
  for (size_t i = 0; i < mp.labels.size(); ++i) s += (i ? ", " : "") + mp.labels[i];
  return s.empty() ? "none" : s;
}

std::vector<std::pair<int, Side>> sides_on_surface(const MultiPatch& mp, int label) {
  std::vector<std::pair<int, Side>> out;
  for (const auto& b : mp.boundaries)
    if (b.label == label) out.emplace_back(b.patch, b.side);
  for (const auto& itf : mp.interfaces)
    if (itf.surface == label) {
      const bool a_inside = mp.patches.at(itf.patch_a).material >= mp.patches.at(itf.patch_b).material;
      out.emplace_back(a_inside ? itf.patch_a : itf.patch_b, a_inside ? itf.side_a : itf.side_b);
    }
  return out;
}

std::vector<int> labels_with_sides(const MultiPatch& mp) {
  std::vector<bool> used(mp.labels.size(), false);
  for (const auto& b : mp.boundaries)
    if (b.label >= 0 && b.label < static_cast<int>(used.size())) used[b.label] = true;
  for (const auto& itf : mp.interfaces)
    if (itf.surface >= 0 && itf.surface < static_cast<int>(used.size())) used[itf.surface] = true;
  std::vector<int> out;
  for (size_t l = 0; l < used.size(); ++l)
    if (used[l]) out.push_back(static_cast<int>(l));
  return out;
}

}  // namespace igaprep::spline
