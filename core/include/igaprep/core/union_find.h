#pragma once
// Disjoint sets of the integers 0..n-1, optionally with a relative sign
// (parity) per element, for orientations that must agree along a chain
// (e.g. the edge directions of adjacent patches).
//
// The root of a set is always its smallest element, so everything derived
// from roots (an order of the sets, a representative's position) depends
// only on which elements were joined, not on the order of the joins.
#include <utility>
#include <vector>

namespace igaprep {

class UnionFind {
 public:
  explicit UnionFind(int n) : parent_(static_cast<std::size_t>(n)), parity_(static_cast<std::size_t>(n), 1) {
    for (int i = 0; i < n; ++i) parent_[static_cast<std::size_t>(i)] = i;
  }

  int size() const { return static_cast<int>(parent_.size()); }

  // The root of x's set (its smallest element).
  int find(int x) { return find_with_parity(x).first; }

  // (root, parity of x relative to the root: +1 or -1).
  std::pair<int, int> find_with_parity(int x) {
    int root = x, sign = 1;
    while (parent_[at(root)] != root) {
      sign *= parity_[at(root)];
      root = parent_[at(root)];
    }
    // Path compression: every element on the way now points at the root,
    // with its parity relative to the root.
    for (int node = x, to_root = sign; node != root;) {
      const int next = parent_[at(node)];
      const int next_to_root = to_root * parity_[at(node)];
      parent_[at(node)] = root;
      parity_[at(node)] = to_root;
      node = next;
      to_root = next_to_root;
    }
    return {root, sign};
  }

  // Joins the sets of a and b, requiring parity(a) * parity(b) = relation
  // (+1 or -1; plain sets always use +1). Returns false, and changes
  // nothing, when a and b are already joined with the other relation.
  bool unite(int a, int b, int relation = 1) {
    auto [ra, sa] = find_with_parity(a);
    auto [rb, sb] = find_with_parity(b);
    if (ra == rb) return sa * sb == relation;
    if (rb < ra) std::swap(ra, rb);
    parent_[at(rb)] = ra;
    parity_[at(rb)] = sa * sb * relation;
    return true;
  }

 private:
  static std::size_t at(int i) { return static_cast<std::size_t>(i); }
  std::vector<int> parent_;
  std::vector<int> parity_;  // of an element relative to its parent
};

}  // namespace igaprep
