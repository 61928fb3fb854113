#include "cut/mt/part_record.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace mtcut::cut {

void PartRecord::add(const Mt& mt, const MtChangeReport& commit, const MtChangeReport* held) {
  if (owned_.size() < mt.num_tets()) owned_.resize(mt.num_tets(), kNone);
  for (TetId t : commit.made_tets) {
    num_owned_ += owned_[t.index()] == kNone;
    owned_[t.index()] = kCommitted;
  }
  if (made_.size() < mt.num_vertices()) made_.resize(mt.num_vertices(), kNone);
  for (const MadeVertex& made : commit.made_vertices) {
    points_.emplace(made.key, made.id);
    made_[made.id.index()] = kCommitted;
  }
  // A held point that a committed piece uses is committed with it: the
  // held front may be taken back, the committed crack never.
  promoted_.clear();
  bool promoting = false;
  if (!held_points_.empty())
    for (TetId t : commit.made_tets)
      for (VertId v : mt.tet(t))
        if (made_[v.index()] == kHeld) {
          made_[v.index()] = kCommitted;
          promoting = true;
        }
  if (promoting)
    for (auto it = held_points_.begin(); it != held_points_.end();) {
      if (made_[it->second.index()] != kCommitted) {
        ++it;
        continue;
      }
      points_.emplace(it->first, it->second);
      promoted_.emplace_back(it->first, it->second);
      held_points_.erase(it++);
    }
  if (met_) {
    owed_.add(mt, commit, held);
    return;
  }
  const auto change = [&](FragId f) {
    if (f.valid() && f != mt.root() && f != mt.drain()) changed_.push_back(f);
  };
  for (const TetReplacement& r : commit.replaced) {
    change(r.birth);
    change(r.death);
  }
  for (FragId f : decomposed_fragments(commit)) change(f);
}

void PartRecord::meet_old_crack(const Mt& mt, const MtChangeReport* held) {
  if (met_) return;
  std::vector<FragId> changed = changed_;
  std::sort(changed.begin(), changed.end());
  changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
  owed_.enter_whole(mt, changed, held);
  met_ = true;
}

std::vector<MadeVertex> PartRecord::hold(const Mt& mt, MtChangeReport& front) {
  release();
  if (owned_.size() < mt.num_tets()) owned_.resize(mt.num_tets(), kNone);
  if (made_.size() < mt.num_vertices()) made_.resize(mt.num_vertices(), kNone);
  for (TetId t : front.made_tets) {
    if (owned_[t.index()] != kNone) throw std::logic_error("PartRecord::hold: a held piece is committed");
    owned_[t.index()] = kHeld;
    held_tets_.push_back(t);
    for (VertId v : mt.tet(t))
      if (made_[v.index()] == kNone) made_[v.index()] = kUsed;
  }
  // The front's points its pieces use are held; the marks on the others
  // (the mesh's own vertices) go.
  std::vector<MadeVertex> used, unused;
  used.reserve(front.made_vertices.size());
  for (MadeVertex& made : front.made_vertices) {
    if (made_[made.id.index()] != kUsed) {
      unused.push_back(std::move(made));
      continue;
    }
    made_[made.id.index()] = kHeld;
    held_points_.emplace(made.key, made.id);
    used.push_back(std::move(made));
  }
  front.made_vertices = std::move(used);
  for (TetId t : held_tets_)
    for (VertId v : mt.tet(t))
      if (made_[v.index()] == kUsed) made_[v.index()] = kNone;
  return unused;
}

void PartRecord::release() {
  for (TetId t : held_tets_) owned_[t.index()] = kNone;
  for (const auto& [key, v] : held_points_) made_[v.index()] = kNone;
  held_tets_.clear();
  held_points_.clear();
}

void PartRecord::take_back(const MtChangeReport* commit, Before before) {
  if (commit) {
    for (TetId t : commit->made_tets)
      if (t.index() < owned_.size() && owned_[t.index()]) {
        owned_[t.index()] = kNone;
        --num_owned_;
      }
    for (const MadeVertex& made : commit->made_vertices)
      if (made.id.index() < made_.size() && made_[made.id.index()]) {
        points_.erase(made.key);
        made_[made.id.index()] = kNone;
      }
    for (const auto& [key, v] : promoted_) {
      points_.erase(key);
      made_[v.index()] = kHeld;
      held_points_.emplace(key, v);
    }
  }
  promoted_.clear();
  owed_ = std::move(before.owed);
  met_ = before.met;
  front_ = std::move(before.front);
  changed_.resize(std::min(changed_.size(), before.changed));
}

std::vector<MadeVertex> PartRecord::committed_points() const {
  std::vector<MadeVertex> out;
  out.reserve(points_.size());
  for (const auto& [key, id] : points_) {
    MadeVertex& m = out.emplace_back();
    m.id = id;
    m.key = key;
  }
  std::sort(out.begin(), out.end(), [](const MadeVertex& a, const MadeVertex& b) { return a.id < b.id; });
  return out;
}

void PartRecord::renumber(const Mt::Compaction& compaction) {
  release();
  promoted_.clear();
  std::vector<std::uint8_t> owned(owned_.size(), 0);
  for (std::size_t t = 0; t < owned_.size(); ++t)
    if (owned_[t] && compaction.tet_map[t] >= 0) owned[static_cast<std::size_t>(compaction.tet_map[t])] = kCommitted;
  owned_ = std::move(owned);
  std::vector<std::uint8_t> made(made_.size(), 0);
  for (std::size_t v = 0; v < made_.size(); ++v)
    if (made_[v] && compaction.vertex_map[v] >= 0) made[static_cast<std::size_t>(compaction.vertex_map[v])] = kCommitted;
  made_ = std::move(made);
  // Keys name vertices by id (sorted; the renumbering keeps their order).
  absl::flat_hash_map<PointKey, VertId, PointKeyHash> points;
  points.reserve(points_.size());
  for (const auto& [old_key, v] : points_) {
    PointKey key = old_key;
    for (std::int32_t& id : key.ids)
      if (id >= 0) id = compaction.vertex_map[static_cast<std::size_t>(id)];
    points.emplace(key, compaction.vertex(v));
  }
  points_ = std::move(points);
  owed_.renumber(compaction);
}

engine::ValidationReport PartRecord::validate(const Mt& mt, const MtChangeReport* since) const {
  engine::ValidationReport report;
  std::size_t owned = 0;
  std::vector<std::uint8_t> used(mt.num_vertices(), 0);
  std::size_t held = 0;
  for (std::size_t t = 0; t < owned_.size(); ++t) {
    if (!owned_[t]) continue;
    owned += owned_[t] == kCommitted;
    held += owned_[t] == kHeld;
    if (t >= mt.num_tets() || !mt.alive(TetId(t))) {
      report.add("part record: committed or held piece " + std::to_string(t) + " is not a live tet");
      continue;
    }
    for (VertId v : mt.tet(TetId(t))) used[v.index()] |= owned_[t];
  }
  if (owned != num_owned_) report.add("part record: committed pieces miscounted");
  if (held != held_tets_.size()) report.add("part record: held pieces miscounted");
  for (const auto& [key, v] : held_points_)
    if (!v.valid() || v.index() >= mt.num_vertices() || !(used[v.index()] & kHeld) || made_[v.index()] != kHeld)
      report.add("part record: held point " + std::to_string(v.value) + " used by no held piece, or not marked");
  std::size_t made = 0;
  for (const auto& [key, v] : points_) {
    if (!v.valid() || v.index() >= mt.num_vertices() || !(used[v.index()] & kCommitted))
      report.add("part record: committed point " + std::to_string(v.value) + " used by no committed piece");
    else if (made_[v.index()] != kCommitted)
      report.add("part record: committed point " + std::to_string(v.value) + " not marked made");
  }
  for (std::uint8_t m : made_) made += m == kCommitted;
  if (made != points_.size()) report.add("part record: committed points miscounted");
  if (!met_ && !owed_.empty()) report.add("part record: a ledger before the part met an older crack");
  for (FragId f : changed_)
    if (f.index() >= mt.num_fragments())
      report.add("part record: changed fragment " + std::to_string(f.value) + " is not in the MT");
  for (auto& p : owed_.validate(mt, since).problems) report.add("part record: " + p);
  return report;
}

}  // namespace mtcut::cut
