#include <algorithm>
#include <vector>

#include "igaprep/param/polycube_2d.h"

namespace igaprep::param {
namespace {

// One side of a box (a hole or an arm) across one axis: its coordinate,
// which box it belongs to, and where it is written back.
struct BoxSide {
  double value = 0.0;
  int box = -1;  // -1: a side of the outer rectangle, which stays
  int slot = 0;  // index into the box's (umin, vmin, umax, vmax)
};

// Groups of sides whose coordinates lie within `tolerance` of the group's
// first; each group of two or more boxes moves onto one coordinate.
void merge_axis(std::vector<BoxSide> sides, double tolerance, std::vector<Eigen::Vector4d>& boxes) {
  std::sort(sides.begin(), sides.end(), [](const BoxSide& a, const BoxSide& b) { return a.value < b.value; });
  for (std::size_t first = 0; first < sides.size();) {
    std::size_t end = first + 1;
    while (end < sides.size() && sides[end].value - sides[first].value <= tolerance) ++end;
    std::vector<int> seen;
    bool same_box = false, outer = false;
    double sum = 0.0, target = 0.0;
    for (std::size_t i = first; i < end; ++i) {
      sum += sides[i].value;
      if (sides[i].box < 0) {
        outer = true;
        target = sides[i].value;
      } else if (std::find(seen.begin(), seen.end(), sides[i].box) != seen.end()) {
        same_box = true;
      } else {
        seen.push_back(sides[i].box);
      }
    }
    if (!outer) target = sum / static_cast<double>(end - first);
    if (end - first > 1 && !same_box)
      for (std::size_t i = first; i < end; ++i)
        if (sides[i].box >= 0) boxes[static_cast<std::size_t>(sides[i].box)](sides[i].slot) = target;
    first = end;
  }
}

}  // namespace

void merge_close_sides(RectilinearDomain& domain, double tolerance) {
  std::vector<Eigen::Vector4d> boxes = domain.holes;
  for (const DomainArm& arm : domain.arms) boxes.push_back(arm_box(domain, arm));
  for (int axis = 0; axis < 2; ++axis) {
    const double extent = axis == 0 ? domain.width : domain.height;
    std::vector<BoxSide> sides{{0.0, -1, axis}, {extent, -1, axis + 2}};
    for (std::size_t b = 0; b < boxes.size(); ++b)
      for (int slot : {axis, axis + 2}) sides.push_back({boxes[b](slot), static_cast<int>(b), slot});
    merge_axis(std::move(sides), tolerance, boxes);
  }
  const std::size_t holes = domain.holes.size();
  for (std::size_t h = 0; h < holes; ++h) domain.holes[h] = boxes[h];
  for (std::size_t a = 0; a < domain.arms.size(); ++a)
    domain.arms[a] = arm_from_box(domain.arms[a].side, boxes[holes + a], domain.width, domain.height);
}

}  // namespace igaprep::param
