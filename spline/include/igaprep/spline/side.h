#pragma once
// A side of a patch, after G+Smo's boxSide: 1 = u0, 2 = u1, 3 = v0, 4 = v1,
// 5 = w0, 6 = w1 (0: none). That numbering is the one of the model files
// (HDF5, G+Smo XML); the member functions are the only place where it is
// turned into a direction and an end, so no call site computes
// (side - 1) / 2 or side - 1 itself.
#include <array>

namespace igaprep::spline {

class Side {
 public:
  constexpr Side() = default;
  // Implicit, like boxSide(int): sides are stored and read as their index.
  constexpr Side(int index) : index_(index) {}
  constexpr operator int() const { return index_; }

  constexpr int index() const { return index_; }  // 1..6
  constexpr bool valid() const { return index_ >= 1 && index_ <= 6; }

  // The side at the low (parameter false) or high (true) end of direction 0..2.
  static Side of(int direction, bool parameter);
  // All six sides in order u0, u1, v0, v1, w0, w1.
  static constexpr std::array<Side, 6> all() { return {{Side(1), Side(2), Side(3), Side(4), Side(5), Side(6)}}; }

  // The functions below throw bad_input for a side outside 1..6.
  int direction() const;                          // the normal direction: 0 (u), 1 (v) or 2 (w)
  bool parameter() const;                         // false at the low end (u0, v0, w0), true at the high end
  int array_index() const;                        // 0..5, for arrays of the six sides
  Side opposite() const;                          // the other end of the same direction
  std::array<int, 2> tangent_directions() const;  // the two other directions, increasing

 private:
  int index_ = 0;
};

inline constexpr Side kU0{1}, kU1{2}, kV0{3}, kV1{4}, kW0{5}, kW1{6};

}  // namespace igaprep::spline
