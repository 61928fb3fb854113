#pragma once
// Point location over the MT's tets in rest space, at every resolution at
// once, and in a frontier.
//
// Why this shape. The cutter must find every MT tet a cut polygon crosses,
// in every fragment (paper, section 4, step 1), and replace each by its
// pieces; the simulator must find the frontier tet holding a point (to
// carry a hidden vertex). One BVH over all live tets serves both: a
// frontier query is the same walk with a membership filter (a point lies
// in one tet per resolution that differs there, a few dozen at most). The
// cutter's replacements are applied in place (remove + insert, which only
// grows boxes on one root-to-leaf path) and the tree is rebuilt, by its
// owner between cuts, once the edits outnumber half the tets. Edits that
// undo edits wear nothing: a tet that left its slot takes it again when it
// is inserted back, and a tet joining a leaf takes an entry a removed tet
// left in that leaf's list (a stroke's front, split and taken back frame
// after frame in the same tets, cut_retraction.h).

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/mt/bvh.h"
#include "engine/mt/mt.h"
#include "engine/validation.h"

namespace mtcut::engine {

class Frontier;

// The box of tet t's corners.
Aabb tet_box(const Mt& mt, TetId t);
// tet_box(mt, t).overlaps(box), axis after axis: a query box thin along one
// axis (a cut quad) rejects most tets on the first.
inline bool tet_box_overlaps(const Mt& mt, TetId t, const Aabb& box) {
  const Tet& v = mt.tet(t);
  const Vec3 &a = mt.position(v[0]), &b = mt.position(v[1]), &c = mt.position(v[2]), &d = mt.position(v[3]);
  for (int k = 0; k < 3; ++k) {
    const double lo = std::min(std::min(a[k], b[k]), std::min(c[k], d[k]));
    const double hi = std::max(std::max(a[k], b[k]), std::max(c[k], d[k]));
    if (!(lo <= box.hi[k] && box.lo[k] <= hi)) return false;
  }
  return true;
}
// p lies in the closed tet t (exact orientation tests).
bool tet_contains(const Mt& mt, TetId t, const Vec3& p);
// The first of `tets` holding p (none if none). For small local searches:
// a vertex that a refinement brings back lies in the tets the refined
// fragment created, so its deformed position is found among those.
TetId locate_among(const Mt& mt, std::span<const TetId> tets, const Vec3& p);

class TetBvh {
 public:
  TetBvh() = default;
  explicit TetBvh(const Mt& mt) { rebuild(mt); }
  // Over all live tets of the MT.
  void rebuild(const Mt& mt);

  // Live tets in the index (tombstones excluded).
  std::size_t size() const { return indexed_; }
  // A box holding every indexed tet (the root's; edits keep it holding
  // them). Empty when nothing is indexed.
  Aabb bounds() const { return bvh_.empty() ? Aabb{} : bvh_.nodes()[0].box; }
  std::size_t bytes() const;

  // Every indexed tet whose box overlaps `box` (candidates: the caller tests
  // the exact geometry). visit(TetId) returns false to stop.
  template <class Visit>
  void for_each_overlapping(const Mt& mt, const Aabb& box, Visit&& visit) const {
    for_each_overlapping(mt, box, [](const Aabb&) { return true; }, visit);
  }
  // The same, skipping the nodes whose box keep_node(const Aabb&) rejects:
  // a filter the caller knows to hold for every box around a tet it wants
  // (a cut skips the nodes lying on one side of its plane, most of the
  // tree when the cut spans the object).
  template <class KeepNode, class Visit>
  void for_each_overlapping(const Mt& mt, const Aabb& box, KeepNode&& keep_node, Visit&& visit) const {
    for_each_overlapping(mt, box, keep_node, [](TetId) { return true; }, visit);
  }
  // The same, passing over the tets keep_tet(TetId) rejects before their
  // boxes are read (a part's cut skips its committed pieces, which crowd
  // the nodes along its plane).
  template <class KeepNode, class KeepTet, class Visit>
  void for_each_overlapping(const Mt& mt, const Aabb& box, KeepNode&& keep_node, KeepTet&& keep_tet,
                            Visit&& visit) const {
    const auto nodes = bvh_.nodes();
    bvh_.walk(
        [&](std::int32_t n) {
          const Aabb& node = nodes[static_cast<std::size_t>(n)].box;
          return node.overlaps(box) && keep_node(node);
        },
        [&](std::int32_t n) {
          return visit_leaf(n, [&](TetId t) { return !keep_tet(t) || !tet_box_overlaps(mt, t, box) || visit(t); });
        });
  }
  // Every indexed tet holding p (closed tets, exact).
  template <class Visit>
  void for_each_containing(const Mt& mt, const Vec3& p, Visit&& visit) const {
    const auto nodes = bvh_.nodes();
    bvh_.walk([&](std::int32_t n) { return nodes[static_cast<std::size_t>(n)].box.contains(p); },
              [&](std::int32_t n) {
                return visit_leaf(n, [&](TetId t) { return !tet_contains(mt, t, p) || visit(t); });
              });
  }
  // A tet of the whole MT holding p (none outside the object).
  TetId locate(const Mt& mt, const Vec3& p) const;
  // The frontier tet holding p (none outside the frontier's mesh).
  TetId locate_in(const Mt& mt, const Frontier& frontier, const Vec3& p) const;

  // Edits that follow the MT's, made after it: t left the MT / t joined it;
  // `pieces` took the place of `old` (the cutter's R(t); old already killed,
  // pieces already added; each piece's corners are old's or convex
  // combinations of them, as a split makes them: validate() finds a piece
  // that pokes out of old's leaf). Edits never rebuild: they are cheap (one
  // root-to-leaf path), and a rebuild (about 10 ms at 60k tets) must not
  // land inside the cutter's time-critical budget. The owner calls refresh()
  // at a quiet moment instead.
  void remove(TetId t);
  void insert(const Mt& mt, TetId t);
  void replace(const Mt& mt, TetId old, std::span<const TetId> pieces);
  // Room for tet ids below `tets` and for `insertions` more inserted tets,
  // so that a cut that knows what it adds grows each array once.
  void reserve(std::size_t tets, std::size_t insertions);

  // A point to roll the index back to: every edit from mark() on is undone
  // by roll_back() (removed tets back in their slots, inserted ones dropped,
  // boxes left as grown), as when the MT is edited and then restored
  // exactly (cut/mt/cut_retraction.h). Insertions are appended, so taking
  // them back leaves no wear. One mark at a time; a rebuild forgets it.
  struct Mark {
    std::size_t extra = 0, indexed = 0, edits = 0;
    std::uint64_t generation = 0;
  };
  Mark mark();
  // Undoes the edits since `m` (the MT must be back to the tets it had then).
  // Throws std::logic_error when `m` is not the mark held.
  void roll_back(const Mark& m);
  bool marked() const { return marking_; }

  // Follows Mt::compact: the same tree and boxes over the tets' new ids
  // (every indexed tet is live, so kept), in O(n_slots + n_tets), where a
  // rebuild would cost the cut's frame about 10 ms at 60k tets. The mark
  // holds when the compaction kept every tet removed since it (else it is
  // forgotten: marked() says which).
  void renumber(const Mt::Compaction& compaction);

  // The edits since the last rebuild (slots left empty and tets in the
  // leaves' lists: what a query tests beyond a fresh tree's tets; an entry
  // a removed tet left is skipped, and the leaf's next tet takes it)
  // outnumber half the indexed tets: queries have slowed down enough that
  // a rebuild pays for itself.
  bool worn() const { return edits_ > indexed_ / 2 + 64; }
  std::size_t edits() const { return edits_; }
  // Rebuilds when worn(); returns whether it did.
  bool refresh(const Mt& mt);

  // The index over `mt` as it is (O(n_tets + n_nodes), for tests): it holds
  // exactly the live tets, each once, where where_ says; every node's box
  // holds its children's, and every leaf's the boxes of its tets, so no
  // query can miss one; the counts add up.
  ValidationReport validate(const Mt& mt) const;

 private:
  // The leaf indexing t (-1 when t is not indexed).
  std::int32_t leaf_of(TetId t) const;
  // Appends the tets not indexed yet to leaf n's list, in one go (n's box
  // and its ancestors' must hold their boxes; where_ covers their ids).
  void append_to_leaf(std::size_t n, std::span<const TetId> tets);
  void grow(std::size_t tets);  // where_ and vacated_ over ids below `tets`

  template <class Visit>
  bool visit_leaf(std::int32_t n, Visit&& visit) const {
    const BvhNode& node = bvh_.nodes()[static_cast<std::size_t>(n)];
    for (std::int32_t i = node.first; i < node.first + node.count; ++i) {
      const std::int32_t t = slot_tet_[static_cast<std::size_t>(i)];
      if (t >= 0 && !visit(TetId(t))) return false;
    }
    for (std::int32_t e = extra_head_[static_cast<std::size_t>(n)]; e >= 0; e = extra_next_[static_cast<std::size_t>(e)]) {
      const std::int32_t t = extra_tet_[static_cast<std::size_t>(e)];
      if (t >= 0 && !visit(TetId(t))) return false;
    }
    return true;
  }

  Bvh bvh_;
  std::vector<std::int32_t> slot_tet_;    // (n_slots) tet in each leaf slot, -1 = removed
  std::vector<std::int32_t> extra_head_;  // (n_nodes) first inserted tet of a leaf, -1 = none
  std::vector<std::int32_t> extra_tet_;   // (n_extra) inserted tets, -1 = removed
  std::vector<std::int32_t> extra_next_;  // (n_extra) next in the leaf's list
  std::vector<std::int32_t> slot_leaf_;   // (n_slots) leaf node holding each slot
  std::vector<std::int32_t> extra_leaf_;  // (n_extra) leaf node of each inserted tet
  std::vector<std::int32_t> where_;       // (n_tets) slot >= 0, extra e as -(e + 2), -1 = not indexed
  std::size_t indexed_ = 0;
  std::vector<std::int32_t> vacated_;    // (n_tets) the slot a removed tet left, -1 = none
  std::size_t edits_ = 0;  // empty slots and listed tets since the last rebuild
  // While marked: every edit since the mark, undone in reverse by roll_back.
  struct Undo {
    enum class Kind : std::uint8_t { kRemoved, kRestored, kReused };
    Kind kind;
    std::int32_t tet;
    std::int32_t where;  // kRemoved: where_ entry it had; kRestored: the slot; kReused: the extra entry
  };
  bool marking_ = false;
  std::uint64_t mark_generation_ = 0;
  std::vector<Undo> undo_;
};

}  // namespace mtcut::engine
