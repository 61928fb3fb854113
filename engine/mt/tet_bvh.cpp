#include "engine/mt/tet_bvh.h"

#include <algorithm>
#include <cassert>
#include <stdexcept>
#include <string>

#include "engine/mt/frontier.h"
#include "engine/reserve_geometric.h"

namespace mtcut::engine {

Aabb tet_box(const Mt& mt, TetId t) {
  Aabb box;
  for (VertId v : mt.tet(t)) box.extend(mt.position(v));
  return box;
}

namespace {

// Tet t's box as the tree holds it: grown by 1e-9 of its largest coordinate.
// Pieces of t (replace()) are convex combinations of its corners, which round
// to within a few ulps of t's box; so pieces of pieces, over up to a million
// generations of cuts, still fit in the box t's leaf was given, and replace()
// needs no box of its own for them (0.3 ms of the 2 ms Table 1's largest cut
// spends replacing tets).
Aabb indexed_box(const Mt& mt, TetId t) {
  Aabb box = tet_box(mt, t);
  const double pad = 1e-9 * std::max(box.lo.cwiseAbs().maxCoeff(), box.hi.cwiseAbs().maxCoeff());
  box.lo.array() -= pad;
  box.hi.array() += pad;
  return box;
}

}  // namespace

bool tet_contains(const Mt& mt, TetId t, const Vec3& p) {
  const auto c = mt.corners(t);
  return orient3d_sign(p, c[1], c[2], c[3]) >= 0 && orient3d_sign(c[0], p, c[2], c[3]) >= 0 &&
         orient3d_sign(c[0], c[1], p, c[3]) >= 0 && orient3d_sign(c[0], c[1], c[2], p) >= 0;
}

TetId locate_among(const Mt& mt, std::span<const TetId> tets, const Vec3& p) {
  for (TetId t : tets)
    if (tet_contains(mt, t, p)) return t;
  return TetId();
}

void TetBvh::rebuild(const Mt& mt) {
  std::vector<Aabb> boxes;
  std::vector<std::int32_t> ids, levels;
  boxes.reserve(mt.num_live_tets());
  ids.reserve(mt.num_live_tets());
  levels.reserve(mt.num_live_tets());
  for (std::size_t i = 0; i < mt.num_tets(); ++i) {
    if (!mt.alive(TetId(i))) continue;
    boxes.push_back(indexed_box(mt, TetId(i)));
    ids.push_back(static_cast<std::int32_t>(i));
    levels.push_back(error_level(mt.error(TetId(i))));
  }
  bvh_.build(boxes, levels);
  const auto items = bvh_.items();
  slot_tet_.resize(items.size());
  where_.assign(mt.num_tets(), -1);
  vacated_.assign(mt.num_tets(), -1);
  for (std::size_t s = 0; s < items.size(); ++s) {
    slot_tet_[s] = ids[static_cast<std::size_t>(items[s])];
    where_[static_cast<std::size_t>(slot_tet_[s])] = static_cast<std::int32_t>(s);
  }
  extra_head_.assign(bvh_.nodes().size(), -1);
  extra_tet_.clear();
  extra_next_.clear();
  extra_leaf_.clear();
  slot_leaf_.assign(items.size(), -1);
  const auto nodes = bvh_.nodes();
  for (std::size_t n = 0; n < nodes.size(); ++n)
    if (nodes[n].leaf())
      for (std::int32_t i = nodes[n].first; i < nodes[n].first + nodes[n].count; ++i)
        slot_leaf_[static_cast<std::size_t>(i)] = static_cast<std::int32_t>(n);
  indexed_ = ids.size();
  edits_ = 0;
  marking_ = false;
  undo_.clear();
}

void TetBvh::renumber(const Mt::Compaction& compaction) {
  const auto map = [&](std::int32_t& t) {
    if (t >= 0) t = compaction.tet_map[static_cast<std::size_t>(t)];
  };
  for (std::int32_t& t : slot_tet_) map(t);
  for (std::int32_t& t : extra_tet_) map(t);
  std::size_t tets = 0;
  for (const std::int32_t t : compaction.tet_map) tets += t >= 0;
  std::vector<std::int32_t> where(tets, -1), vacated(tets, -1);
  for (std::size_t t = 0; t < where_.size() && t < compaction.tet_map.size(); ++t) {
    const std::int32_t to = compaction.tet_map[t];
    if (to < 0) continue;
    where[static_cast<std::size_t>(to)] = where_[t];
    vacated[static_cast<std::size_t>(to)] = vacated_[t];
  }
  where_ = std::move(where);
  vacated_ = std::move(vacated);
  // The mark holds while every tet edited since it was kept (a held cut's
  // replaced tets, dead, which its retraction brings back).
  for (Undo& u : undo_) {
    if (!marking_) break;
    u.tet = compaction.tet_map[static_cast<std::size_t>(u.tet)];
    if (u.tet < 0) {
      marking_ = false;
      ++mark_generation_;
      undo_.clear();
    }
  }
}

TetBvh::Mark TetBvh::mark() {
  marking_ = true;
  undo_.clear();
  return {extra_tet_.size(), indexed_, edits_, ++mark_generation_};
}

void TetBvh::roll_back(const Mark& m) {
  if (!marking_ || m.generation != mark_generation_ || m.extra > extra_tet_.size())
    throw std::logic_error("TetBvh::roll_back: not the index's current mark");
  // Entries inserted since the mark leave their leaves' lists (they were
  // pushed on the lists' heads) and the arrays.
  for (std::size_t e = extra_tet_.size(); e-- > m.extra;) {
    const std::int32_t t = extra_tet_[e];
    if (t >= 0) where_[static_cast<std::size_t>(t)] = -1;
    std::int32_t& head = extra_head_[static_cast<std::size_t>(extra_leaf_[e])];
    while (head >= static_cast<std::int32_t>(m.extra)) head = extra_next_[static_cast<std::size_t>(head)];
  }
  extra_tet_.resize(m.extra);
  extra_next_.resize(m.extra);
  extra_leaf_.resize(m.extra);
  // The other edits since the mark, undone in reverse: tets removed go
  // back where they were, tets put back in their slots leave them again,
  // entries of removed tets that others took are removed ones again.
  for (auto it = undo_.rbegin(); it != undo_.rend(); ++it) {
    const auto t = static_cast<std::size_t>(it->tet);
    const std::int32_t w = it->where;
    switch (it->kind) {
      case Undo::Kind::kRemoved:
        if (w >= 0) {
          slot_tet_[static_cast<std::size_t>(w)] = it->tet;
          vacated_[t] = -1;
        } else if (static_cast<std::size_t>(-w - 2) < m.extra) {
          extra_tet_[static_cast<std::size_t>(-w - 2)] = it->tet;
        } else {
          continue;  // inserted after the mark: gone with it
        }
        where_[t] = w;
        break;
      case Undo::Kind::kRestored:
        slot_tet_[static_cast<std::size_t>(w)] = -1;
        vacated_[t] = w;
        where_[t] = -1;
        break;
      case Undo::Kind::kReused:
        if (static_cast<std::size_t>(w) >= m.extra) continue;  // gone with the entries made since
        extra_tet_[static_cast<std::size_t>(w)] = -1;
        where_[t] = -1;
        break;
    }
  }
  indexed_ = m.indexed;
  edits_ = m.edits;
  marking_ = false;
  undo_.clear();
}

std::size_t TetBvh::bytes() const {
  return bvh_.bytes() + (slot_tet_.capacity() + extra_head_.capacity() + extra_tet_.capacity() +
                         extra_next_.capacity() + where_.capacity() + vacated_.capacity() + slot_leaf_.capacity() + extra_leaf_.capacity()) *
                            sizeof(std::int32_t);
}

TetId TetBvh::locate(const Mt& mt, const Vec3& p) const {
  TetId found;
  for_each_containing(mt, p, [&](TetId t) {
    found = t;
    return false;
  });
  return found;
}

TetId TetBvh::locate_in(const Mt& mt, const Frontier& frontier, const Vec3& p) const {
  TetId found;
  const auto nodes = bvh_.nodes();
  bvh_.walk([&](std::int32_t n) { return nodes[static_cast<std::size_t>(n)].box.contains(p); },
            [&](std::int32_t n) {
              return visit_leaf(n, [&](TetId t) {
                if (!frontier.has_tet(t) || !tet_contains(mt, t, p)) return true;
                found = t;
                return false;
              });
            });
  return found;
}

void TetBvh::remove(TetId t) {
  if (t.index() >= where_.size() || where_[t.index()] == -1) return;
  const std::int32_t w = where_[t.index()];
  if (marking_) undo_.push_back({Undo::Kind::kRemoved, t.value, w});
  if (w >= 0) {
    slot_tet_[static_cast<std::size_t>(w)] = -1;
    vacated_[t.index()] = w;
    ++edits_;
  } else {
    extra_tet_[static_cast<std::size_t>(-w - 2)] = -1;  // a query skips it (no box test): free for the leaf's next tet
    if (edits_ > 0) --edits_;
  }
  where_[t.index()] = -1;
  --indexed_;
}

void TetBvh::insert(const Mt& mt, TetId t) {
  assert(mt.alive(t));
  if (bvh_.empty()) {
    rebuild(mt);
    return;
  }
  grow(mt.num_tets());
  if (where_[t.index()] != -1) return;
  // A tet that left its slot takes it again (its leaf's box holds it).
  if (const std::int32_t w = vacated_[t.index()]; w >= 0 && slot_tet_[static_cast<std::size_t>(w)] == -1) {
    if (marking_) undo_.push_back({Undo::Kind::kRestored, t.value, w});
    slot_tet_[static_cast<std::size_t>(w)] = t.value;
    where_[t.index()] = w;
    vacated_[t.index()] = -1;
    ++indexed_;
    if (edits_ > 0) --edits_;
    return;
  }
  const Aabb box = indexed_box(mt, t);
  // Down one path, growing each box on it, towards the child that grows least.
  auto nodes = bvh_.mutable_nodes();
  std::size_t n = 0;
  for (;;) {
    nodes[n].box.extend(box);
    if (nodes[n].leaf()) break;
    const auto left = static_cast<std::size_t>(nodes[n].first);
    Aabb grown_left = nodes[left].box, grown_right = nodes[left + 1].box;
    grown_left.extend(box), grown_right.extend(box);
    const double cost_left = grown_left.volume() - nodes[left].box.volume();
    const double cost_right = grown_right.volume() - nodes[left + 1].box.volume();
    n = cost_left <= cost_right ? left : left + 1;
  }
  append_to_leaf(n, std::span<const TetId>(&t, 1));
}

std::int32_t TetBvh::leaf_of(TetId t) const {
  if (t.index() >= where_.size()) return -1;
  const std::int32_t w = where_[t.index()];
  if (w == -1) return -1;
  return w >= 0 ? slot_leaf_[static_cast<std::size_t>(w)] : extra_leaf_[static_cast<std::size_t>(-w - 2)];
}

void TetBvh::grow(std::size_t tets) {
  if (where_.size() < tets) where_.resize(tets, -1);
  if (vacated_.size() < tets) vacated_.resize(tets, -1);
}

void TetBvh::append_to_leaf(std::size_t n, std::span<const TetId> tets) {
  const std::size_t first = extra_tet_.size();
  std::int32_t head = extra_head_[n];
  std::int32_t free = head;  // the next entry of the list to look at for a removed one
  for (TetId t : tets) {
    if (where_[t.index()] != -1) continue;  // already indexed
    while (free >= 0 && extra_tet_[static_cast<std::size_t>(free)] >= 0) free = extra_next_[static_cast<std::size_t>(free)];
    if (free >= 0) {  // an entry a removed tet left: its removal is undone
      if (marking_) undo_.push_back({Undo::Kind::kReused, t.value, free});
      extra_tet_[static_cast<std::size_t>(free)] = t.value;
      where_[t.index()] = -free - 2;
      ++indexed_;
      ++edits_;
      continue;
    }
    const auto e = static_cast<std::int32_t>(extra_tet_.size());
    extra_tet_.push_back(t.value);
    extra_next_.push_back(head);
    head = e;
    where_[t.index()] = -e - 2;
  }
  const std::size_t added = extra_tet_.size() - first;
  extra_leaf_.resize(extra_tet_.size(), static_cast<std::int32_t>(n));
  extra_head_[n] = head;
  indexed_ += added;
  edits_ += added;
}

void TetBvh::reserve(std::size_t tets, std::size_t insertions) {
  reserve_geometric(where_, tets);
  reserve_geometric(vacated_, tets);
  reserve_geometric(extra_tet_, extra_tet_.size() + insertions);
  reserve_geometric(extra_next_, extra_next_.size() + insertions);
  reserve_geometric(extra_leaf_, extra_leaf_.size() + insertions);
}

void TetBvh::replace(const Mt& mt, TetId old, std::span<const TetId> pieces) {
  // The pieces of a split lie in the old tet, so in the (padded) box of its
  // leaf: they join that leaf directly, with no walk from the root and no
  // box grown.
  const std::int32_t leaf = leaf_of(old);
  remove(old);
  if (leaf < 0) {
    for (TetId t : pieces) insert(mt, t);
    return;
  }
  grow(mt.num_tets());
  append_to_leaf(static_cast<std::size_t>(leaf), pieces);  // in one go: each array grown once
}

ValidationReport TetBvh::validate(const Mt& mt) const {
  ValidationReport report;
  const auto tet_name = [](std::int32_t t) { return "TetBvh: tet " + std::to_string(t); };
  const auto holds = [](const Aabb& outer, const Aabb& inner) {
    return outer.contains(inner.lo) && outer.contains(inner.hi);
  };
  const auto nodes = bvh_.nodes();
  // Each tet listed once: where_ points back at the one slot or extra
  // entry that lists it, in a leaf whose box holds the tet.
  std::size_t listed = 0;
  const auto check_entry = [&](std::int32_t t, std::int32_t where, std::int32_t leaf) {
    ++listed;
    if (t < 0 || static_cast<std::size_t>(t) >= mt.num_tets() || !mt.alive(TetId(t))) {
      report.add(tet_name(t) + " is indexed but not a live tet");
      return;
    }
    if (static_cast<std::size_t>(t) >= where_.size() || where_[static_cast<std::size_t>(t)] != where)
      report.add(tet_name(t) + " is listed where where_ does not say");
    if (leaf < 0 || static_cast<std::size_t>(leaf) >= nodes.size() || !nodes[static_cast<std::size_t>(leaf)].leaf())
      report.add(tet_name(t) + " is in no leaf");
    else if (!holds(nodes[static_cast<std::size_t>(leaf)].box, tet_box(mt, TetId(t))))
      report.add(tet_name(t) + " pokes out of its leaf's box");
  };
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    const BvhNode& node = nodes[n];
    if (!node.leaf()) {
      for (std::size_t c = 0; c < 2; ++c) {
        const std::size_t child = static_cast<std::size_t>(node.first) + c;
        if (child >= nodes.size() || child <= n)
          report.add("TetBvh: node " + std::to_string(n) + " has child " + std::to_string(child) + " out of order");
        else if (!nodes[child].box.empty() && !holds(node.box, nodes[child].box))
          report.add("TetBvh: node " + std::to_string(n) + "'s box does not hold child " + std::to_string(child));
      }
      continue;
    }
    for (std::int32_t i = node.first; i < node.first + node.count; ++i) {
      const std::int32_t t = slot_tet_[static_cast<std::size_t>(i)];
      if (t >= 0) check_entry(t, i, static_cast<std::int32_t>(n));
      if (slot_leaf_[static_cast<std::size_t>(i)] != static_cast<std::int32_t>(n))
        report.add("TetBvh: slot " + std::to_string(i) + " names the wrong leaf");
    }
    for (std::int32_t e = extra_head_[n]; e >= 0; e = extra_next_[static_cast<std::size_t>(e)]) {
      const std::int32_t t = extra_tet_[static_cast<std::size_t>(e)];
      if (t >= 0) check_entry(t, -e - 2, static_cast<std::int32_t>(n));
      if (extra_leaf_[static_cast<std::size_t>(e)] != static_cast<std::int32_t>(n))
        report.add("TetBvh: inserted entry " + std::to_string(e) + " names the wrong leaf");
    }
  }
  // Every live tet indexed; the count of indexed tets right.
  for (std::size_t t = 0; t < mt.num_tets(); ++t)
    if (mt.alive(TetId(t)) && (t >= where_.size() || where_[t] == -1))
      report.add(tet_name(static_cast<std::int32_t>(t)) + " is live but not indexed");
  if (listed != indexed_)
    report.add("TetBvh: " + std::to_string(listed) + " tets listed, " + std::to_string(indexed_) + " counted");
  // A slot a tet left is empty until that tet takes it again.
  for (std::size_t t = 0; t < vacated_.size(); ++t)
    if (vacated_[t] >= 0 && (static_cast<std::size_t>(vacated_[t]) >= slot_tet_.size() ||
                             slot_tet_[static_cast<std::size_t>(vacated_[t])] != -1 || where_[t] >= 0))
      report.add(tet_name(static_cast<std::int32_t>(t)) + " left a slot that is not empty, or holds another");
  return report;
}

bool TetBvh::refresh(const Mt& mt) {
  if (!worn()) return false;
  rebuild(mt);
  return true;
}

}  // namespace mtcut::engine
