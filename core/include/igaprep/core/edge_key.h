#pragma once
// One 64-bit key per undirected edge {a, b} of a mesh (hash maps of edges).
#include <algorithm>
#include <cstdint>

namespace igaprep {

inline std::uint64_t edge_key(int a, int b) {
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
}

}  // namespace igaprep
