#pragma once
// A set of handles over a dense universe 0..n-1 with O(1) insert, erase and
// membership, and a compact list of its members for iteration. The frontier
// keeps its tets, vertices and fragments in these so that a refine or coarsen
// step costs only the elements it touches (swap-remove with a back-index fix,
// as Box2D does for its body arrays).

#include <cassert>
#include <cstdint>
#include <span>
#include <vector>

namespace mtcut::engine {

template <class Handle>
class IndexSet {
 public:
  // Grows the universe to n (never shrinks; members stay).
  void grow(std::size_t n) {
    if (n > position_.size()) position_.resize(n, -1);
  }
  std::size_t universe() const { return position_.size(); }

  bool contains(Handle h) const { return h.index() < position_.size() && position_[h.index()] >= 0; }
  std::size_t size() const { return members_.size(); }
  bool empty() const { return members_.empty(); }
  std::span<const Handle> members() const { return members_; }

  void insert(Handle h) {
    assert(h.index() < position_.size() && position_[h.index()] < 0);
    position_[h.index()] = static_cast<std::int32_t>(members_.size());
    members_.push_back(h);
  }
  void erase(Handle h) {
    assert(contains(h));
    const std::int32_t at = position_[h.index()];
    const Handle last = members_.back();
    members_[static_cast<std::size_t>(at)] = last;
    position_[last.index()] = at;
    members_.pop_back();
    position_[h.index()] = -1;
  }
  void clear() {
    for (Handle h : members_) position_[h.index()] = -1;
    members_.clear();
  }
  std::size_t bytes() const {
    return members_.capacity() * sizeof(Handle) + position_.capacity() * sizeof(std::int32_t);
  }

 private:
  std::vector<Handle> members_;         // (size) in no particular order
  std::vector<std::int32_t> position_;  // (universe) index in members_, -1 when absent
};

}  // namespace mtcut::engine
