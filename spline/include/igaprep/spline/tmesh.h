#pragma once
// The T-mesh of one tensor-product patch in index space (issue 18). Each
// element of the patch starts as the unit cube of its knot-span indices; a
// box of level l is split in half across direction l mod 3 (by default), and before a box
// is split every coarser box near it is split first (the closure of
// Morgenstern 2016, SIAM J. Numer. Anal. 54, which keeps a trivariate
// T-spline of odd degree analysis-suitable). Coordinates are integers (an
// index times kTScale), so every split is exact and shared faces compare
// equal.
#include <array>
#include <cstdint>
#include <vector>

namespace igaprep::spline {

using TCoord = std::int64_t;
inline constexpr TCoord kTScale = TCoord(1) << 20;  // at most 20 splits per direction

struct TBox {
  std::array<TCoord, 3> lo{}, hi{};
  int level = 0;
  int element = 0;  // the patch element (u fastest) the box lies in
};

class TMesh {
 public:
  // The tensor grid of elements[d] spans per direction; degrees (odd) set
  // the size of the closure's neighbourhood. A box of level l is split
  // across split_directions[l mod their count]: all three by default, or
  // e.g. {0, 1} for a mesh refined in u and v only (the 2-D scheme of
  // Morgenstern and Peterseim 2015, extruded along w).
  TMesh(const std::array<int, 3>& elements, const std::array<int, 3>& degrees,
        const std::vector<int>& split_directions = {0, 1, 2});

  const std::vector<TBox>& boxes() const { return boxes_; }
  const std::array<int, 3>& elements() const { return elements_; }
  const std::array<int, 3>& degrees() const { return degrees_; }
  int split_direction_count() const { return static_cast<int>(split_directions_.size()); }
  TCoord extent(int d) const { return static_cast<TCoord>(elements_[static_cast<std::size_t>(d)]) * kTScale; }
  // The leaves inside one patch element (boxes() indices).
  // Whether any box was split (otherwise the mesh is the patch's elements).
  bool refined() const { return boxes_.size() != in_element_.size(); }
  const std::vector<int>& boxes_in(int element) const { return in_element_[static_cast<std::size_t>(element)]; }

  // Splits leaf `box` across its level's direction, after every coarser box
  // that meets its neighbourhood. Indices of other boxes stay valid: the
  // box keeps its index as its lower half, the upper half is appended.
  // Throws internal_error past 20 splits in one direction.
  void refine(int box);
  // The split alone, without the closure: for meshes made by hand (a mesh
  // so made may not be analysis-suitable; check_analysis_suitable says).
  void split(int box);

 private:
  bool meets_neighbourhood(const TBox& near, const TBox& of) const;
  int coarser_neighbour(const TBox& of) const;

  std::array<int, 3> elements_, degrees_;
  std::vector<int> split_directions_;
  std::vector<TBox> boxes_;
  std::vector<std::vector<int>> in_element_;
};

}  // namespace igaprep::spline
