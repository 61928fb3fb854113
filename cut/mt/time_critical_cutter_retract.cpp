// TimeCriticalCutter (time_critical_cutter.h): taking cuts back. A
// provisional cut retracted whole, a part's front taken back only where
// its grown polygon changes its splits (the rest kept and held in the
// record), and a part's frame taken back after a refusal.
#include "cut/mt/time_critical_cutter.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace mtcut::cut {

std::optional<CutRetraction> TimeCriticalCutter::retract(Mt& mt, TetBvh& bvh) {
  balanced_.reset();  // the front goes whole, or was not checked
  if (provisional_queued_) {
    queue_.pop_back();
    provisional_queued_ = false;
  }
  std::optional<Transaction> tx;
  if (active_ && active_->provisional) {
    tx = std::move(active_->tx);
    active_.reset();
  } else if (held_) {
    tx = std::move(held_);
    held_.reset();
  }
  std::optional<CutRetraction> out;
  if (tx) out = take_back(mt, bvh, *tx);
  if (kept_) {  // the part's front kept this frame, its own front not finished
    std::vector<std::uint8_t> all(kept_->changes.replaced.size(), 1);
    CutRetraction more = retract_replacements(mt, bvh, kept_->changes, all);
    more.unused = std::move(kept_->changes.made_vertices);
    kept_->record->release();
    keep_committed(more, kept_->record.get());
    kept_.reset();
    if (!out) out.emplace();
    out->append(std::move(more));
  }
  if (out) pieces_stale_ = pieces_stale_ || out->fragments_removed > 0;
  return out;
}

CutRetraction TimeCriticalCutter::take_back(Mt& mt, TetBvh& bvh, Transaction& tx) {
  CutRetraction out;
  if (tx.combined) {
    std::vector<std::uint8_t> all(tx.changes.replaced.size(), 1);
    out = retract_replacements(mt, bvh, tx.changes, all);
    out.unused = std::move(tx.changes.made_vertices);
  } else {
    out = retract_cut(mt, bvh, tx.changes, tx.fragments_before, tx.bvh_mark ? &*tx.bvh_mark : nullptr);
  }
  if (tx.front_of) {
    tx.front_of->release();
    keep_committed(out, tx.front_of.get());
  }
  return out;
}

void TimeCriticalCutter::follow_fragments(const Mt& mt, MtChangeReport& held) {
  for (TetReplacement& r : held.replaced) {
    const TetId piece = held.made_tets[r.first];
    r.birth = mt.birth(piece);
    r.death = mt.death(piece);
  }
}

void TimeCriticalCutter::keep_committed(CutRetraction& retraction, const PartRecord* record) {
  if (!record) return;
  std::erase_if(retraction.unused, [&](const MadeVertex& m) { return record->made(m.id); });
}

std::optional<CutRetraction> TimeCriticalCutter::keep_front(Mt& mt, TetBvh& bvh, const CutPolygon& polygon) {
  Transaction tx = std::move(*held_);
  held_.reset();
  PartRecord& record = *part_->record;
  record.release();
  // Vertices this near the plane may be put on the cut by the cut's other
  // tets (the classifier's snap reach is a fraction of an edge, and no
  // edge is longer than the model's box): their tets are split afresh.
  const engine::Aabb box = bvh.bounds();
  const double reach = 10 * std::max(def_.cut.snap, ClassifierDef::kMinSnap) * (box.hi - box.lo).norm();
  std::vector<std::uint8_t> take =
      kept_front_splits(mt, tx.changes, polygon, record, def_.cut.snap, reach, &workspace_.classifier);
  for (std::uint8_t& t : take) t = !t;
  if (balanced_ && balanced_->record == part_->record) {
    balanced_->taken.emplace();
    balanced_->taken->subtract(mt, tx.changes, take);
  } else {
    balanced_.reset();
  }
  CutRetraction out = retract_replacements(mt, bvh, tx.changes, take);
  out.unused = record.hold(mt, tx.changes);
  // The front's tets no commit owns and the record does not hold are the
  // ones taken back: the frame's commit searches them, and where the
  // polygon grew.
  engine::Aabb front;
  for (TetId t : out.revived)
    for (VertId v : mt.tet(t)) front.extend(mt.position(v));
  record.set_front(front);
  if (!tx.changes.replaced.empty()) kept_ = Kept{part_->record, std::move(tx.changes)};
  keep_committed(out, &record);
  return out;
}

void TimeCriticalCutter::take_back_frame(Mt& mt, TetBvh& bvh, const std::shared_ptr<PartRecord>& record,
                                         CutSelect select, RunResult& result) {
  balanced_.reset();
  // A refused commit leaves its front queued behind it, to be split against it.
  if (select == CutSelect::kComplete && !queue_.empty() && queue_.front().record == record &&
      queue_.front().select == CutSelect::kFront) {
    queue_.pop_front();
    provisional_queued_ = false;
  }
  if (!frame_ || frame_->record != record.get()) {
    record->set_front(std::nullopt);  // its tets may be whole: the next frame searches them all
    return;
  }
  Frame frame = std::move(*frame_);
  frame_.reset();
  if (frame.commit) {
    const Transaction& c = *frame.commit;
    CutRetraction retraction = retract_cut(mt, bvh, c.changes, c.fragments_before);
    if (kept_ && kept_->record == record && retraction.fragments_removed > 0) follow_fragments(mt, kept_->changes);
    if (frame.call == calls_ && frame.reported_from) {
      // This call reported the commit: it is dropped from the report, and
      // the caller, which maps the report before the refusal, never sees it.
      result.changes.truncate(*frame.reported_from);
    } else {
      result.refused->append(std::move(retraction));
      result.refused_reported_vertices += c.changes.made_vertices.size();  // reported when it was kept
    }
    result.pieces.reset();  // counted after the commit, perhaps
    pieces_stale_ = true;
  }
  record->take_back(frame.commit ? &frame.commit->changes : nullptr, std::move(frame.before));
  searched_.reset();
  if (!frame.previous) return;  // the part's first frame: nothing was cut before it
  if (part_ && part_->record.get() == record.get()) part_->last = *frame.previous;
  // The last frame's front again: the caller runs the cutter once more
  // after mapping the refusal (cut_stroke_step, World::step).
  queue_provisional({.polygon = *frame.previous, .record = record, .select = CutSelect::kFront, .stroke = true});
}

}  // namespace mtcut::cut
