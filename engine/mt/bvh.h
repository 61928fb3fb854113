#pragma once
// Axis-aligned boxes and a bounding volume hierarchy over them, shared by
// point location over the MT's tets (tet_bvh.h) and by selective
// refinement's index over fragments (selective_refinement.h).
//
// Why this shape. Both users need "which items' boxes could matter here",
// over items of many sizes (an MT holds every resolution at once), built in
// O(n log n) and small. Nodes are an array addressed by index (children of
// an internal node are consecutive), items a permutation array; the users
// keep their per-node data (error bounds, overflow lists) in parallel arrays.

#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "engine/predicates.h"

namespace mtcut::engine {

struct Aabb {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = Vec3::Constant(-std::numeric_limits<double>::infinity());

  void extend(const Vec3& p) { lo = lo.cwiseMin(p), hi = hi.cwiseMax(p); }
  void extend(const Aabb& b) { lo = lo.cwiseMin(b.lo), hi = hi.cwiseMax(b.hi); }
  bool empty() const { return !(lo.x() <= hi.x()); }
  bool contains(const Vec3& p) const { return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all(); }
  bool overlaps(const Aabb& b) const { return (lo.array() <= b.hi.array()).all() && (b.lo.array() <= hi.array()).all(); }
  Vec3 center() const { return 0.5 * (lo + hi); }
  double diagonal() const { return empty() ? 0.0 : (hi - lo).norm(); }
  double volume() const { return empty() ? 0.0 : (hi - lo).prod(); }
  // Distance from p to the nearest / farthest point of the box. Both are
  // monotone under box inclusion in floating point too (a box inside
  // another is never nearer than it, nor farther than its far corner).
  double min_distance(const Vec3& p) const;
  double max_distance(const Vec3& p) const;
};

// The box of a point set (empty for none).
inline Aabb box_of(std::span<const Vec3> points) {
  Aabb box;
  for (const Vec3& p : points) box.extend(p);
  return box;
}

// floor(log2(size)) for the `levels` of Bvh::build (a very low level for 0).
inline std::int32_t error_level(float size) { return size > 0.0f ? std::ilogb(size) : -1000; }

struct BvhNode {
  Aabb box;
  std::int32_t first = 0;  // leaf: first item; internal: left child (right = first + 1)
  std::int32_t count = 0;  // leaf: number of items (> 0); internal: 0
  bool leaf() const { return count > 0; }
};

class Bvh {
 public:
  // Builds over items 0..boxes.size()-1; leaves hold at most leaf_size
  // items. With `levels` (one small integer per item, e.g. log2 of its
  // size), the top of the tree separates the levels first (splitting at the
  // middle level of a range), and median splits along the longest axis of
  // the boxes' centres follow within one level. An MT holds every
  // resolution at once; mixing a coarse tet into a node of fine ones would
  // make the node as big as the coarse tet, and a point query would visit
  // every level's worth of nodes at every depth.
  void build(std::span<const Aabb> boxes, std::span<const std::int32_t> levels = {}, int leaf_size = 4);

  bool empty() const { return nodes_.empty(); }
  std::span<const BvhNode> nodes() const { return nodes_; }
  std::span<BvhNode> mutable_nodes() { return nodes_; }
  // Item ids in leaf order: leaf items are items()[first .. first + count).
  std::span<const std::int32_t> items() const { return items_; }
  std::size_t bytes() const { return nodes_.capacity() * sizeof(BvhNode) + items_.capacity() * sizeof(std::int32_t); }

  // Depth-first walk: enter(node_index) returns whether to look inside the
  // node; leaf(node_index) is called for each leaf entered and returns
  // false to stop the whole walk.
  template <class Enter, class Leaf>
  void walk(Enter&& enter, Leaf&& leaf) const {
    if (nodes_.empty()) return;
    std::int32_t stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const std::int32_t n = stack[--top];
      if (!enter(n)) continue;
      const BvhNode& node = nodes_[static_cast<std::size_t>(n)];
      if (node.leaf()) {
        if (!leaf(n)) return;
      } else {
        stack[top++] = node.first + 1;
        stack[top++] = node.first;
      }
    }
  }

 private:
  std::vector<BvhNode> nodes_;
  std::vector<std::int32_t> items_;
};

}  // namespace mtcut::engine
