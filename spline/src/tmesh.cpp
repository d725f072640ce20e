#include "igaprep/spline/tmesh.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "igaprep/core/error.h"

namespace igaprep::spline {

TMesh::TMesh(const std::array<int, 3>& elements, const std::array<int, 3>& degrees, const std::vector<int>& split_directions)
    : elements_(elements), degrees_(degrees), split_directions_(split_directions) {
  if (split_directions.empty()) throw bad_input("T-mesh: no direction to split");
  for (const int d : split_directions)
    if (d < 0 || d > 2) throw bad_input("T-mesh: split direction " + std::to_string(d) + " is not 0, 1 or 2");
  for (int d = 0; d < 3; ++d) {
    if (elements[static_cast<std::size_t>(d)] < 1) throw bad_input("T-mesh: a direction without elements");
    if (degrees[static_cast<std::size_t>(d)] < 1 || degrees[static_cast<std::size_t>(d)] % 2 == 0)
      throw bad_input("T-mesh: local refinement needs odd degrees, got " +
                      std::to_string(degrees[static_cast<std::size_t>(d)]) + " in direction " + std::to_string(d));
  }
  const int count = elements[0] * elements[1] * elements[2];
  in_element_.resize(static_cast<std::size_t>(count));
  for (int k = 0; k < elements[2]; ++k)
    for (int j = 0; j < elements[1]; ++j)
      for (int i = 0; i < elements[0]; ++i) {
        TBox b;
        const int at[3] = {i, j, k};
        for (std::size_t d = 0; d < 3; ++d) {
          b.lo[d] = at[d] * kTScale;
          b.hi[d] = (at[d] + 1) * kTScale;
        }
        b.element = i + elements[0] * (j + elements[1] * k);
        in_element_[static_cast<std::size_t>(b.element)].push_back(static_cast<int>(boxes_.size()));
        boxes_.push_back(b);
      }
}

// The neighbourhood of a box: the open box about its midpoint reaching
// (p_d + 3) / 4 of its own width beyond it in each direction (1.5 widths
// for cubics), wide enough for the supports of the functions a split makes.
// The size is ours, not taken from the paper: every refined mesh is checked
// for dual compatibility when it is extracted (tspline_functions.h).
bool TMesh::meets_neighbourhood(const TBox& near, const TBox& of) const {
  for (std::size_t d = 0; d < 3; ++d) {
    const double size = static_cast<double>(of.hi[d] - of.lo[d]);
    const double reach = 0.5 * size + 0.5 * size * (0.5 * (degrees_[d] + 1) + 1.0);
    const double mid_of = 0.5 * static_cast<double>(of.lo[d] + of.hi[d]);
    const double mid_near = 0.5 * static_cast<double>(near.lo[d] + near.hi[d]);
    const double half_near = 0.5 * static_cast<double>(near.hi[d] - near.lo[d]);
    if (!(std::abs(mid_near - mid_of) < reach + half_near)) return false;
  }
  return true;
}

// A coarser leaf than `of` that meets its neighbourhood, or -1; only the
// elements the neighbourhood reaches are searched.
int TMesh::coarser_neighbour(const TBox& of) const {
  std::array<int, 3> first{}, last{};
  for (std::size_t d = 0; d < 3; ++d) {
    const TCoord size = of.hi[d] - of.lo[d];
    const TCoord reach = size * (degrees_[d] + 3) / 4 + 1;  // the neighbourhood's reach beyond the box, rounded up
    first[d] = static_cast<int>(std::max<TCoord>(0, (of.lo[d] - reach) / kTScale));
    last[d] = static_cast<int>(std::min<TCoord>(elements_[d] - 1, (of.hi[d] + reach) / kTScale));
  }
  for (int k = first[2]; k <= last[2]; ++k)
    for (int j = first[1]; j <= last[1]; ++j)
      for (int i = first[0]; i <= last[0]; ++i)
        for (const int b : in_element_[static_cast<std::size_t>(i + elements_[0] * (j + elements_[1] * k))])
          if (boxes_[static_cast<std::size_t>(b)].level < of.level && meets_neighbourhood(boxes_[static_cast<std::size_t>(b)], of))
            return b;
  return -1;
}

void TMesh::refine(int box) {
  for (int coarser = coarser_neighbour(boxes_[static_cast<std::size_t>(box)]); coarser >= 0;
       coarser = coarser_neighbour(boxes_[static_cast<std::size_t>(box)]))
    refine(coarser);
  split(box);
}

void TMesh::split(int box) {
  TBox& b = boxes_[static_cast<std::size_t>(box)];
  const std::size_t d = static_cast<std::size_t>(split_directions_[static_cast<std::size_t>(b.level) % split_directions_.size()]);
  const TCoord width = b.hi[d] - b.lo[d];
  if (width < 2 || width % 2 != 0) throw internal_error("T-mesh: more than 20 splits in direction " + std::to_string(d));
  TBox upper = b;
  b.hi[d] = b.lo[d] + width / 2;
  upper.lo[d] = b.hi[d];
  ++b.level;
  ++upper.level;
  in_element_[static_cast<std::size_t>(b.element)].push_back(static_cast<int>(boxes_.size()));
  boxes_.push_back(upper);
}

}  // namespace igaprep::spline
