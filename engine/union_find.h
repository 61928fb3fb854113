#pragma once
// Disjoint sets over 0..n-1 (union by smaller index, path halving): a set's
// representative is its smallest member, which callers may rely on.

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

namespace mtcut::engine {

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }

  std::int32_t find(std::int32_t x) {
    while (parent_[static_cast<std::size_t>(x)] != x) {
      const std::int32_t up = parent_[static_cast<std::size_t>(parent_[static_cast<std::size_t>(x)])];
      parent_[static_cast<std::size_t>(x)] = up;
      x = up;
    }
    return x;
  }
  // Joins the sets of a and b; false when they were one already.
  bool unite(std::int32_t a, std::int32_t b) {
    a = find(a), b = find(b);
    if (a == b) return false;
    parent_[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
    return true;
  }
  // x represents its set.
  bool is_root(std::int32_t x) const { return parent_[static_cast<std::size_t>(x)] == x; }
  std::size_t size() const { return parent_.size(); }

 private:
  std::vector<std::int32_t> parent_;
};

}  // namespace mtcut::engine
