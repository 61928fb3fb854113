#pragma once
// The cut record of a stroke's straight part, cut progressively (DESIGN.md,
// "Progressive cutting", after Mor and Kanade).
//
// Why a record. Every frame the part's polygon grows by the blade's sweep.
// Recutting the whole polygon each frame (and taking the last frame's cut
// back) costs the whole part per frame; yet a tet the polygon crosses
// completely (every edge it straddles crosses the plane inside the polygon,
// no vertex on the cut) has the same split under every later polygon of the
// part, since they share one plane and only grow. So each frame is cut in
// two: the tets crossed completely are committed, split for good, and join
// the record; the tets of the front (the blade's segment, a vertex on the
// cut, the outline's sides) are split provisionally, and those whose
// configuration the next frame changes are taken back and split afresh
// from their originals (the held front, below). The record holds what the
// next frames must agree with:
//   - the plane: the part's first polygon's, which every later polygon of
//     the part is projected onto (CutPolygon::on_plane_of), so exact sides
//     never change from frame to frame;
//   - the committed pieces (`owns`), which no later cut of the part
//     searches: a piece of a split is never cut again;
//   - the committed points by key: a later split through an edge the
//     committed crack crosses takes the same vertex, whatever the polygon's
//     outline does there, and counts the edge as crossed.
// A committed tet has no vertex on the cut, and the plane does not move, so
// the sides of its vertices stay as they were (a vertex that a later frame
// snaps onto the cut would change that: the cutter's guard, cut_guard.h,
// takes such a frame's cut back).
// Fragments are decomposed only by committed cuts: a provisional split
// (the front) never separates its tet, so it never separates a fragment.
//
// The held front. Most of a front is split the same way frame after frame
// (the blade moves less than a tet per step at a stylus's rate): the
// cutter keeps those splits (TimeCriticalCutter::recut) and holds them
// here, so that the frame's cuts treat them as they treat the committed
// ones: their pieces are not searched, and their points are taken by key.
// They stay provisional: the part's end, or a frame that changes them,
// takes them back.

#include <cstdint>
#include <optional>
#include <vector>

#include "absl/container/flat_hash_map.h"
#include "cut/cut_polygon.h"
#include "cut/mt/fragment_ledger.h"
#include "cut/mt/mt_change_report.h"
#include "engine/mt/bvh.h"
#include "engine/mt/mt.h"
#include "engine/validation.h"

namespace mtcut::cut {

using engine::Mt;
using engine::TetId;
using engine::VertId;

// Which of the tets a cut finds it changes (MtCutDef::select).
enum class CutSelect : std::uint8_t {
  kAll,       // every one: a cut for good, or a part's last
  kComplete,  // splits of tets the polygon crosses completely: committed to the record
  kFront,     // the rest (partial splits, relabels): provisional, no fragment decomposed
};

class PartRecord {
 public:
  explicit PartRecord(const CutPolygon& plane) : plane_(plane) {}

  // The part's plane (its first polygon).
  const CutPolygon& plane() const { return plane_; }
  // t is a committed piece or a held one: no cut of the part searches it.
  bool owns(TetId t) const { return t.index() < owned_.size() && owned_[t.index()] != kNone; }
  // v is a committed or held point (of the part's one planar crack).
  bool made(VertId v) const { return v.index() < made_.size() && made_[v.index()] != kNone; }
  // The committed or held point of `key`, or none.
  VertId point(const PointKey& key) const {
    if (const auto it = points_.find(key); it != points_.end()) return it->second;
    const auto it = held_points_.find(key);
    return it == held_points_.end() ? VertId() : it->second;
  }
  std::size_t num_owned() const { return num_owned_; }  // committed pieces
  std::size_t num_held() const { return held_tets_.size(); }
  // The committed points (key and id only), in id order: with the part's
  // end, what the stroke's crack records (stroke_crack.h).
  std::vector<MadeVertex> committed_points() const;

  // Where the part's crossed tets that no commit owns lie (beside what the
  // polygon's growth adds): the box of the tets the last committed cut left
  // whole, its front. nullopt: anywhere in the polygon (a refused commit
  // left its tets whole too).
  const std::optional<engine::Aabb>& front() const { return front_; }
  void set_front(std::optional<engine::Aabb> box) { front_ = std::move(box); }

  // What the commits owe the fragments (fragment_ledger.h): a commit
  // splits the finer tets of a fragment its polygon crosses completely, and
  // only the front or the end the coarser ones the outline passes through.
  // The cutter's guard checks the front and the end against it once the
  // part has met an older crack (a cut of it splits a piece of an earlier
  // cut: a turn's junction, an older stroke), so a part commits there as
  // anywhere else. Until then each of its cuts is one planar cut through
  // tets no cut had touched, conforming by construction, and the guard
  // skips that check (cut_guard.h): the record keeps only which fragments
  // the commits changed, and the ledger is empty.
  const FragmentLedger& owed() const { return owed_; }
  bool met_old_crack() const { return met_; }
  // The part's next cut splits a piece of an earlier cut; called before
  // that cut changes the MT. The fragments the commits changed enter the
  // ledger by what their tets sum to (they balanced before the part's first
  // commit), `held` (the front kept beside the cut, may be null) taken out.
  void meet_old_crack(const Mt& mt, const MtChangeReport* held);

  // A committed cut finished (and was kept): its pieces and points join,
  // and what it owes the fragments.
  // `held`: the front kept beside it (FragmentLedger::add).
  void add(const Mt& mt, const MtChangeReport& commit, const MtChangeReport* held = nullptr);
  // The front kept from the last frame (`front`: its replacements, and the
  // points its cuts made): its pieces and the points they use are held,
  // in place of what was held before. The points no piece uses leave
  // `front`, returned. release(): none is.
  std::vector<MadeVertex> hold(const Mt& mt, MtChangeReport& front);
  void release();

  // A frame taken back (its commit or front refused, the commit retracted
  // if it was kept): the commit's pieces and points leave, and the ledger,
  // whether the part had met an older crack and the front are again as
  // they were before it.
  struct Before {
    FragmentLedger owed;
    bool met = false;
    std::optional<engine::Aabb> front;
    std::size_t changed = 0;  // fragments the commits had changed before the part met an older crack
  };
  Before before_commit() const { return {owed_, met_, front_, changed_.size()}; }
  void take_back(const MtChangeReport* commit, Before before);
  // The MT was compacted (Mt::compact): ids follow; the held front is
  // released (its holder holds it again, renumbered).
  void renumber(const Mt::Compaction& compaction);

  // Every owned tet is alive, every point a vertex some owned tet uses
  // (held ones: some held tet);
  // the ledger is empty until the part meets an older crack, then holds
  // what the fragments it names are out of balance by, with `since` (the
  // changes made after the last commit: the part's held front, or its cut
  // in progress; may be null).
  engine::ValidationReport validate(const Mt& mt, const MtChangeReport* since = nullptr) const;

 private:
  // What owned_ and made_ say of a tet or vertex (kUsed: hold()'s mark,
  // only while it runs).
  enum Mark : std::uint8_t { kNone = 0, kCommitted = 1, kHeld = 2, kUsed = 3 };
  CutPolygon plane_;
  std::vector<std::uint8_t> owned_;  // (tets) kCommitted or kHeld pieces
  std::size_t num_owned_ = 0;
  std::vector<std::uint8_t> made_;   // (vertices) kCommitted or kHeld points
  std::optional<engine::Aabb> front_;
  FragmentLedger owed_;
  bool met_ = false;
  // The fragments (not the root or the drain) the commits changed before
  // the part met an older crack, in commit order, repeated.
  std::vector<FragId> changed_;
  absl::flat_hash_map<PointKey, VertId, PointKeyHash> points_;
  std::vector<TetId> held_tets_;
  absl::flat_hash_map<PointKey, VertId, PointKeyHash> held_points_;
  // Held points the last commit's pieces use, committed by it (take_back
  // holds them again).
  std::vector<std::pair<PointKey, VertId>> promoted_;
};

}  // namespace mtcut::cut
