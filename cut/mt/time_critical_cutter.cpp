#include "cut/mt/time_critical_cutter.h"

#include "cut/mt/cut_guard.h"
#include "engine/input_error.h"
#include "engine/stopwatch.h"
#include "engine/tet_geometry.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace mtcut::cut {
namespace {

using Clock = std::chrono::steady_clock;

// The mean edge length of the tets `changes` replaced that the root creates
// (the finest), or of all of them when none is.
double mean_finest_edge(const Mt& mt, const MtChangeReport& changes) {
  double finest = 0, all = 0;
  std::size_t n_finest = 0, n_all = 0;
  for (const TetReplacement& r : changes.replaced) {
    const engine::Tet& v = mt.tet(r.old);
    double sum = 0;
    for (const auto& e : engine::kTetEdges) sum += (mt.position(v[e[0]]) - mt.position(v[e[1]])).norm();
    all += sum;
    n_all += 6;
    if (r.birth == mt.root()) {  // r.old is dead: its fragments are the replacement's
      finest += sum;
      n_finest += 6;
    }
  }
  if (n_finest > 0) return finest / static_cast<double>(n_finest);
  return n_all > 0 ? all / static_cast<double>(n_all) : 0.0;
}

}  // namespace

TimeCriticalCutter::TimeCriticalCutter(const TimeCriticalCutterDef& def) : def_(def), table_(def.cut.scheme) {}

void TimeCriticalCutter::submit(const Mt& mt, const CutPolygon& polygon, std::vector<Vec3> geometry) {
  if (provisional_held()) throw std::logic_error("TimeCriticalCutter: a provisional cut is held; retract it first");
  if (!geometry.empty() && geometry.size() != mt.num_vertices())
    throw std::invalid_argument("TimeCriticalCutter::submit: " + std::to_string(geometry.size()) +
                                " positions for " + std::to_string(mt.num_vertices()) + " MT vertices");
  queue_.push_back({.polygon = polygon, .geometry = std::move(geometry)});
}

void TimeCriticalCutter::submit_provisional(const CutPolygon& polygon) {
  queue_provisional({.polygon = polygon});
}

void TimeCriticalCutter::queue_provisional(Queued q) {
  if (provisional_pending()) throw std::logic_error("TimeCriticalCutter: a provisional cut is held; retract it first");
  q.provisional = true;
  queue_.push_back(std::move(q));
  provisional_queued_ = true;
}

const MtChangeReport* TimeCriticalCutter::provisional_changes() const {
  if (active_ && active_->provisional) return &active_->tx.changes;
  return held_ ? &held_->changes : nullptr;
}

std::optional<CutRetraction> TimeCriticalCutter::recut(Mt& mt, TetBvh& bvh, std::span<const CutPolygon> ended,
                                                       std::span<const std::uint8_t> turned_back,
                                                       const std::optional<CutPolygon>& current, bool plane_fixed) {
  if (turned_back.size() != ended.size())
    throw std::invalid_argument("TimeCriticalCutter::recut: " + std::to_string(turned_back.size()) +
                                " turn flags for " + std::to_string(ended.size()) + " ended parts");
  // The part in progress grows: its front's splits that stay as they are
  // are kept (keep_front), unless another cut is queued or in progress (it
  // would search the kept pieces).
  // The part in progress, grown by this frame (none when a part ended, or
  // when the frame's polygon has no area on its plane).
  std::optional<CutPolygon> grown;
  if (ended.empty() && current && part_) grown = on_part_plane(*part_, crossing_ ? past(*current, *crossing_) : *current);
  // A part cut whole whose polygon has moved less than its cut allows
  // (kRedoReach) keeps that cut this frame.
  if (ended.empty() && current && !part_ && !(plane_fixed && !pivot_) && held_ && held_->whole_part &&
      !active_ && queue_.empty() && hausdorff(whole_polygon(*current), *held_->whole_part) <= held_->redo_within)
    return std::nullopt;
  std::optional<CutRetraction> out;
  if (grown && held_ && held_->front_of == part_->record && !active_ && queue_.empty())
    out = keep_front(mt, bvh, *grown);
  if (!out) out = retract(mt, bvh);
  // A part that ends searches its front, the tets its last front and kept
  // splits left (whole again now), and where its polygon grew.
  if (part_ && (!ended.empty() || !current) && out && part_->record->front()) {
    engine::Aabb front = *part_->record->front();
    for (TetId t : out->revived)
      for (VertId v : mt.tet(t)) front.extend(mt.position(v));
    part_->record->set_front(front);
  }
  for (std::size_t i = 0; i < ended.size(); ++i) {
    // The polygon cut for good: the part's (the first ended one, if a part
    // is in progress), or the ended one going on from the last.
    std::shared_ptr<PartRecord> record;
    std::optional<CutPolygon> polygon;
    // The ended polygon starts behind the last turn's edge (crossing_ and
    // pivot_ are exclusive).
    const auto here = [&] { return crossing_ ? past(ended[i], *crossing_) : ended[i]; };
    std::optional<CutPolygon> fallback;
    if (part_) {
      fallback = part_->last;
      // A frame of the part left queued (an earlier cut spent the budget)
      // never ran: the end cuts what it would have, and falls back to the
      // polygon of the last frame that ran (none: no commit to owe).
      drop_queued_frame(*part_->record, fallback);
      if (const std::optional<CutPolygon> on = on_part_plane(*part_, here())) part_->last = *on;
      polygon = part_->last;
      record = part_->record;
      part_.reset();
      frame_.reset();  // the end takes every tet the part's frames left
    } else if (pivot_) {
      polygon = pivoted(*pivot_, ended[i].corners());
    } else {
      polygon = here();
    }
    if (!polygon) polygon = ended[i];
    const CutPolygon* next = i + 1 < ended.size() ? &ended[i + 1] : current ? &*current : nullptr;
    pivot_ = next && !turned_back[i] ? pivot_between(*polygon, *next) : std::nullopt;
    if (pivot_ && (bvh.locate(mt, pivot_->a).valid() || bvh.locate(mt, pivot_->b).valid())) pivot_.reset();
    crossing_.reset();
    if (next && !pivot_) {
      if (std::optional<CutPolygon> crossed = cross_at_turn(mt, bvh, *polygon, *next)) polygon = std::move(crossed);
    }
    if (!record) fallback.reset();
    submit_ended(*polygon, std::move(record), pivot_, std::move(fallback));
  }
  if (!current) {
    if (part_) {  // the stroke ended with nothing more to cut
      // As above: a frame of the part left queued never runs, and the end
      // grows from the polygon of the last frame that ran.
      std::optional<CutPolygon> fallback = part_->last;
      drop_queued_frame(*part_->record, fallback);
      submit_ended(part_->last, part_->record, std::nullopt, std::move(fallback));
    }
    part_.reset();
    frame_.reset();
    pivot_.reset();
    crossing_.reset();
    return out;
  }
  if (part_) {  // no part ended: `grown` is this part's
    CutPolygon before = part_->last;
    if (grown) part_->last = *grown;
    submit_part(*part_, std::move(before));
    return out;
  }
  const CutPolygon polygon = whole_polygon(*current);
  // A part going on from the last one's crack across a gentle turn
  // continues it (stroke_crack.h), which only a cut of its whole polygon
  // does: it is cut whole, pivoting about the edge as the blade goes on,
  // until it ends (again each frame its polygon moved by kRedoReach).
  if (plane_fixed && !pivot_) {
    part_ = Part{std::make_shared<PartRecord>(polygon), polygon};
    submit_part(*part_);
  } else {
    queue_provisional({.polygon = polygon, .stroke = true, .whole_part = true});  // the plane may still turn
  }
  return out;
}

std::optional<CutPolygon> TimeCriticalCutter::on_part_plane(const Part& part, const CutPolygon& polygon) const {
  const CutPolygon& plane = part.record->plane();
  // The part's polygon only grows: what a frame committed stays inside it
  // however the next frame's map to rest space moves the outline, and a
  // polygon already of the plane (a frame whose sweep was not mapped) may
  // cover less than the last one too.
  if (polygon.same_plane(plane) && part.last.box_beyond(polygon).empty()) return polygon;
  std::vector<Vec3> corners = part.last.corners();
  corners.insert(corners.end(), polygon.corners().begin(), polygon.corners().end());
  try {
    return CutPolygon::on_plane_of(plane, corners);
  } catch (const engine::InputError&) {
    return std::nullopt;  // degenerate once projected: the part's last polygon stays
  }
}

void TimeCriticalCutter::submit_ended(const CutPolygon& polygon, std::shared_ptr<PartRecord> record,
                                      const std::optional<Pivot>& next, std::optional<CutPolygon> fallback) {
  if (provisional_pending()) throw std::logic_error("TimeCriticalCutter: a provisional cut is held; retract it first");
  // A part's end searches, as its frames' commits do, its front and where
  // its polygon grew since the last frame: its commits own the rest.
  std::optional<CutPolygon> grown_from = record ? fallback : std::nullopt;
  Queued q{.polygon = polygon,
           .record = std::move(record),
           .grown_from = std::move(grown_from),
           .stroke = true,
           .fallback = std::move(fallback)};
  if (next) q.leading = std::array<Vec3, 2>{next->a, next->b};
  queue_.push_back(std::move(q));
}

void TimeCriticalCutter::submit_part(const Part& part, std::optional<CutPolygon> grown_from) {
  if (provisional_pending()) throw std::logic_error("TimeCriticalCutter: a provisional cut is held; retract it first");
  // This frame grows from where a frame of the part left queued would have.
  drop_queued_frame(*part.record, grown_from);
  queue_.push_back({.polygon = part.last,
                    .record = part.record,
                    .select = CutSelect::kComplete,
                    .grown_from = std::move(grown_from),
                    .stroke = true});
  queue_provisional({.polygon = part.last, .record = part.record, .select = CutSelect::kFront, .stroke = true});
}

void TimeCriticalCutter::drop_queued_frame(const PartRecord& record, std::optional<CutPolygon>& grown_from) {
  if (queue_.empty() || queue_.back().record.get() != &record || queue_.back().select != CutSelect::kComplete) return;
  grown_from = std::move(queue_.back().grown_from);
  queue_.pop_back();
}

void TimeCriticalCutter::extend_geometry(std::span<const MadeVertex> made) {
  // Queued deformed cuts follow the vertices made since they were submitted:
  // each at the same weights of its parents (parents always have lower ids).
  for (Queued& q : queue_) {
    if (q.geometry.empty()) continue;
    for (const MadeVertex& m : made) {
      if (m.id.index() < q.geometry.size()) continue;
      q.geometry.push_back(m.blend([&](VertId parent) { return q.geometry[parent.index()]; }));
    }
  }
}

void TimeCriticalCutter::start_next(const Mt& mt, TetBvh& bvh, const Frontier& frontier) {
  Queued q = std::move(queue_.front());
  queue_.pop_front();
  bvh.refresh(mt);  // between two cuts: the index edits of the last one never rebuild mid-cut
  Active a;
  a.provisional = q.provisional;
  a.record = std::move(q.record);
  a.select = q.select;
  a.fallback = std::move(q.fallback);
  a.is_fallback = q.is_fallback;
  if (q.provisional) provisional_queued_ = false;
  first_cut_vertex_ = std::min(first_cut_vertex_, mt.num_vertices());
  a.tx = Transaction{mt.num_fragments(), mt.num_vertices(), {}, bvh.mark()};
  MtCutDef def = def_.cut;
  def.record = a.record.get();
  def.select = a.select;
  def.decompose = !q.provisional;
  // A part's frame, and its end, search around its front and where its
  // polygon grew (part_record.h): the tets behind are committed.
  std::optional<engine::Aabb> search;
  if (a.record && a.record->front()) {
    if (a.select == CutSelect::kFront) search = a.record->front();
    if (a.select != CutSelect::kFront && q.grown_from) {
      search = a.record->front();
      def.grown_from = &*q.grown_from;
    }
  }
  def.search = search ? &*search : nullptr;
  // The front right behind its kept commit takes the tets the commit found
  // (MtCutDef::candidates): every tet it may change is one of them.
  const std::optional<Searched> searched = std::exchange(searched_, std::nullopt);
  if (searched && a.select == CutSelect::kFront && search && searched->record == a.record.get() &&
      searched->instance == mt.instance() && searched->revision == mt.revision())
    def.candidates = &searched->tets;
  // A polygon of the stroke continues its crack where it starts on it, and
  // makes its front exactly on the edge the next one starts on.
  // (A part's commit and front have no junction: a part that goes on from
  // the last one's crack is cut whole, recut().)
  std::optional<CutContinuation> continuation;
  if (q.stroke && q.select == CutSelect::kAll) {
    continuation = q.leading ? crack_.continuation(q.polygon, (*q.leading)[0], (*q.leading)[1])
                             : crack_.continuation(q.polygon);
    if (!continuation->junctions.empty() || continuation->leading_edge >= 0) def.continuation = &*continuation;
    if (!q.provisional) a.crack_polygon = q.polygon;
  }
  if (q.whole_part) a.whole_part = q.polygon;
  a.cut = std::make_unique<MtCut>(mt, bvh, q.polygon, q.geometry, def, table_, &workspace_);
  if (a.record && a.select == CutSelect::kComplete) {
    frame_ = Frame{.record = a.record.get(), .previous = q.grown_from, .before = a.record->before_commit()};
    // The front: the tets the commit leaves whole, and the kept splits'.
    engine::Aabb front = a.cut->left_whole_box();
    if (kept_ && kept_->record == a.record)
      for (const TetReplacement& r : kept_->changes.replaced)
        for (VertId v : mt.tet(r.old)) front.extend(mt.position(v));
    a.record->set_front(front);
  }
  // A part whose cut splits a piece of an earlier cut meets an older
  // crack: from here on what its commits owe is checked (after the frame's
  // `before`, so that a frame taken back has not met it either).
  if (a.record && !a.record->met_old_crack() && a.cut->changes_earlier_pieces(mt))
    a.record->meet_old_crack(mt, kept_ && kept_->record == a.record ? &kept_->changes : nullptr);
  const auto jobs = a.cut->jobs();
  for (std::size_t j = 0; j < jobs.size(); ++j)
    if (frontier.is_visible(jobs[j])) a.order.push_back(j);
  a.visible = a.order.size();
  for (std::size_t j = 0; j < jobs.size(); ++j)
    if (!frontier.is_visible(jobs[j])) a.order.push_back(j);
  active_ = std::move(a);
}

TimeCriticalCutter::RunResult TimeCriticalCutter::run(Mt& mt, TetBvh& bvh, const Frontier& frontier,
                                                      const CutBudget& budget) {
  const auto start = Clock::now();
  ++calls_;
  RunResult result;
  std::size_t spent = 0, jobs = 0;
  const auto over_budget = [&] {
    if (jobs == 0) return false;
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    return spent >= budget.work || ms >= budget.milliseconds;
  };
  // A part's frame, its commit and its front (part_record.h), is cut
  // whole in the call that reaches it, whatever the budget: the commit
  // leaves the tets the outline passes through whole beside pieces that
  // split their faces, a mesh that conforms only once the front has split
  // them (at every resolution: the commit's jobs spread over calls would
  // show that mesh), and only the front's check covers the commit's edges
  // (cut_guard.h). A frame's work is what the blade swept since the last
  // frame and the blade's own tets; the budget spreads cuts for good (a
  // part's end, a submitted polygon) and the provisional cut of a part
  // with no record.
  const auto in_frame = [](const std::shared_ptr<PartRecord>& record, CutSelect select) {
    return record && select != CutSelect::kAll;
  };
  while (active_ || !queue_.empty()) {
    if (!active_) {
      if (over_budget() && !in_frame(queue_.front().record, queue_.front().select)) break;
      start_next(mt, bvh, frontier);
      result.changes.counts.find_seconds += active_->cut->find_seconds();
    }
    Active& a = *active_;
    MtChangeReport call;  // this call's changes of the active cut
    while (a.next < a.order.size()) {
      const bool in_visible = a.next < a.visible && a.next > 0;
      if (!(def_.visible_at_once && in_visible) && !in_frame(a.record, a.select) && over_budget()) break;
      const std::size_t job = a.order[a.next++];
      spent += a.cut->job_cost(mt, job);
      MtChangeReport changes;
      a.cut->process(mt, bvh, job, changes);
      a.tx.changes.append(changes);
      call.append(changes);
      pieces_stale_ = pieces_stale_ || !changes.fragment_splits.empty();
      a.split_every_level = a.split_every_level ||
                            std::any_of(changes.replaced.begin(), changes.replaced.end(), [&](const TetReplacement& r) {
                              return r.birth == mt.root() && r.death == mt.drain();
                            });
      ++jobs;
      if (!changes.made_vertices.empty() && !queue_.empty()) extend_geometry(changes.made_vertices);
    }
    if (a.next < a.order.size()) {
      result.changes.append(call);
      a.reported_before = true;
      break;
    }
    ++result.cuts_finished;
    ++totals_.cuts_finished;
    FrameCommit commit;  // the frame's commit, checked with its front
    const bool with_commit =
        a.select == CutSelect::kFront && frame_ && frame_->record == a.record.get() && frame_->commit;
    if (with_commit) commit = {&frame_->commit->changes, frame_->commit->first_new_vertex};
    // A front with splits kept from earlier frames: they are of the part's
    // crack, checked when they were made, but where the fragments' balance
    // is checked (cut_guard.h) the whole front pays what the commits owe.
    const bool with_kept = a.select == CutSelect::kFront && kept_ && kept_->record == a.record;
    // A front whose part balanced before the frame is checked by what the
    // frame changed, unless the frame's commit decomposed fragments (the
    // ledger entered them by what their tets sum to).
    std::optional<FragmentLedger> taken;
    if (a.select == CutSelect::kFront && balanced_ && balanced_->record == a.record)
      taken = std::exchange(balanced_->taken, std::nullopt);
    if (!with_commit || !commit.changes->fragment_splits.empty()) taken.reset();
    const engine::ValidationReport guard =
        check_cut(mt, bvh, a.tx.changes, first_cut_vertex_, a.tx.first_new_vertex, a.record.get(), a.select,
                  with_commit ? &commit : nullptr, with_kept ? &kept_->changes : nullptr, taken ? &*taken : nullptr);
    if (a.select == CutSelect::kFront) {
      balanced_.reset();
      if (guard.ok() && a.provisional && a.record && a.record->met_old_crack() && ledger_checked(a.record.get()))
        balanced_ = Balanced{a.record};
    }
    if (!guard.ok()) {
      result.refused = retract_cut(mt, bvh, a.tx.changes, a.tx.fragments_before, &*a.tx.bvh_mark);
      result.refused_reported_vertices = a.tx.changes.made_vertices.size() - call.made_vertices.size();
      result.changes.counts.add(call.counts);
      const std::shared_ptr<PartRecord> record = a.record;
      const CutSelect select = a.select;
      std::optional<CutPolygon> fallback = std::move(a.fallback);
      const bool was_fallback = a.is_fallback;
      active_.reset();  // `a` is gone from here
      if (record && select != CutSelect::kAll) take_back_frame(mt, bvh, record, select, result);
      // A part's end refused: its commits owe the fragments what the end
      // splits, so the part ends where its last frame's front did, which
      // its guard kept (Queued::fallback; the caller runs the cutter again
      // after mapping the refusal).
      if (record && select == CutSelect::kAll && fallback && !was_fallback)
        queue_.push_front({.polygon = *fallback, .record = record, .stroke = true, .fallback = fallback, .is_fallback = true});
      else if (record && select == CutSelect::kAll && fallback)
        queue_.push_front({.polygon = *fallback, .record = record, .select = CutSelect::kFront, .stroke = true});
      pieces_stale_ = pieces_stale_ || result.refused->fragments_removed > 0;
      ++refused_;
      break;  // the caller maps its frontier through the retraction before any later cut
    }
    if (a.record && a.select == CutSelect::kComplete && frame_ && frame_->record == a.record.get()) {
      frame_->call = calls_;
      frame_->reported_from = a.reported_before ? std::nullopt : std::optional(result.changes.length());
    }
    result.changes.append(call);
    // Pieces join finest tets through their vertices and the fragments above
    // them (mt_pieces.h): they fall apart where a fragment splits, or where
    // a tet of every resolution (born of the root, replaced by the drain) is
    // split, which a part's commit may do alone.
    pieces_stale_ = pieces_stale_ || (a.split_every_level && a.select != CutSelect::kFront);
    if (a.record && a.select == CutSelect::kFront) frame_.reset();  // the frame is kept
    if (a.record && a.select == CutSelect::kComplete) {
      const bool beside_kept = kept_ && kept_->record == a.record;
      if (beside_kept && !a.tx.changes.fragment_splits.empty()) follow_fragments(mt, kept_->changes);
      a.record->add(mt, a.tx.changes, beside_kept ? &kept_->changes : nullptr);
      searched_ = Searched{a.record.get(), mt.instance(), mt.revision(), a.cut->candidates()};
      if (frame_ && frame_->record == a.record.get()) {
        a.tx.bvh_mark.reset();  // the index's one mark is the next cut's
        frame_->commit = std::move(a.tx);
      }
    }
    if (a.crack_polygon) {  // with the part's commits, everything its crack holds
      std::vector<MadeVertex> made;
      if (a.record) made = a.record->committed_points();
      made.insert(made.end(), a.tx.changes.made_vertices.begin(), a.tx.changes.made_vertices.end());
      crack_.record(*a.crack_polygon, made);
    }
    // A stroke's crack with a front inside the tissue (a part's commit that
    // left tets whole, and the front cut behind it; a provisional cut whose
    // outline passes through a tet) separates nothing but a lobe it went
    // round: its pieces are counted once a cut leaves no front, or at the
    // part's end, not every frame (a pass over the MT each).
    const bool front_open =
        (a.record && (a.select == CutSelect::kFront ||
                      (a.select == CutSelect::kComplete &&
                       (a.cut->tets_left_whole() > 0 || (kept_ && kept_->record == a.record))))) ||
        (a.provisional && a.cut->tets_crossed_partially() > 0);
    if (a.provisional) {
      held_ = std::move(a.tx);
      if (a.whole_part) {
        held_->whole_part = std::move(a.whole_part);
        held_->redo_within = kRedoReach * mean_finest_edge(mt, held_->changes);
      }
      if (a.record && a.select == CutSelect::kFront) {
        held_->front_of = a.record;
        if (with_kept) {  // the whole front, held in the record until the next frame
          MtChangeReport front = std::move(kept_->changes);
          front.append(held_->changes);
          held_->changes = std::move(front);
          held_->combined = true;
          held_->bvh_mark.reset();
          kept_.reset();
        }
        a.record->hold(mt, held_->changes);  // its points all in use: made by its pieces or kept
      }
    }
    active_.reset();  // `a` is gone from here
    if (def_.report_pieces && pieces_stale_ && !front_open) {
      result.pieces = count_pieces(mt);
      pieces_stale_ = false;
    }
  }
  totals_.total_jobs_done += jobs;
  totals_.seconds += engine::seconds_since(start);
  return result;
}

void TimeCriticalCutter::reserve(Mt& mt) {
  const auto room = [](std::size_t n) { return static_cast<std::size_t>(kRoom * static_cast<double>(n)); };
  const std::size_t vertices = room(mt.num_vertices()), tets = room(std::max(mt.num_tets(), kReclaimMin));
  mt.reserve(vertices, tets);
  workspace_.reserve(vertices, tets, room(mt.num_fragments()));
}

bool TimeCriticalCutter::reclaimable(const Mt& mt) const {
  std::size_t held = held_ ? held_->changes.replaced.size() : 0;  // dead, kept to revive
  if (frame_ && frame_->commit) held += frame_->commit->changes.replaced.size();
  if (kept_) held += kept_->changes.replaced.size();
  const std::size_t droppable = mt.num_dead_tets() - std::min(held, mt.num_dead_tets());
  return !frozen() && droppable >= kReclaimMin && droppable > mt.num_live_tets();
}

std::optional<engine::Mt::Compaction> TimeCriticalCutter::reclaim(Mt& mt, TetBvh& bvh) {
  if (!reclaimable(mt)) return std::nullopt;
  std::vector<TetId> keep;
  if (held_)
    for (const TetReplacement& r : held_->changes.replaced) keep.push_back(r.old);
  if (frame_ && frame_->commit)
    for (const TetReplacement& r : frame_->commit->changes.replaced) keep.push_back(r.old);
  if (kept_)
    for (const TetReplacement& r : kept_->changes.replaced) keep.push_back(r.old);
  engine::Mt::Compaction out = mt.compact(std::min(first_cut_vertex_, mt.num_vertices()), keep);
  bvh.renumber(out);
  if (part_) part_->record->renumber(out);
  crack_.renumber(out);
  searched_.reset();
  if (balanced_) balanced_->taken.reset();  // keyed by the old ids: the frame's front sums it all again
  const auto renumber = [&](Transaction& tx) {
    tx.changes.renumber(out);
    std::size_t kept_before = 0;  // vertices kept below the cut's first
    for (std::size_t v = 0; v < tx.first_new_vertex; ++v) kept_before += out.vertex_map[v] >= 0;
    tx.first_new_vertex = kept_before;
  };
  if (frame_) {
    if (frame_->commit) renumber(*frame_->commit);
    frame_->before.owed.renumber(out);
  }
  if (held_) {
    renumber(*held_);
    if (!bvh.marked()) held_->bvh_mark.reset();  // the index's mark survives when it kept what the held cut removed
  }
  if (kept_) kept_->changes.renumber(out);
  if (part_) {  // its record released what it held: the same front, renumbered
    if (kept_ && kept_->record == part_->record)
      part_->record->hold(mt, kept_->changes);
    else if (held_ && held_->front_of == part_->record)
      part_->record->hold(mt, held_->changes);
  }
  return out;
}

CutterProgress TimeCriticalCutter::progress() const {
  CutterProgress p = totals_;
  p.cuts_queued = queue_.size() + (active_ ? 1 : 0);
  if (active_) {
    p.jobs_done = active_->next;
    p.jobs_pending = active_->order.size() - active_->next;
    p.visible_pending = active_->visible > active_->next ? active_->visible - active_->next : 0;
  }
  return p;
}

engine::ValidationReport TimeCriticalCutter::validate(const Mt& mt) const {
  engine::ValidationReport report;
  if (held_)
    for (auto& p : (held_->combined ? validate_replacements(mt, held_->changes)
                                    : validate_retractable(mt, held_->changes, held_->fragments_before))
                       .problems)
      report.add("cutter: provisional cut: " + p);
  if (kept_)
    for (auto& p : validate_replacements(mt, kept_->changes).problems) report.add("cutter: the kept front: " + p);
  if (active_)
    for (auto& p : validate_retractable(mt, active_->tx.changes, active_->tx.fragments_before).problems)
      report.add("cutter: cut in progress: " + p);
  if (provisional_queued_ && (queue_.empty() || !queue_.back().provisional))
    report.add("cutter: a provisional cut is counted as queued but the queue's last entry is not one");
  if (part_) {
    // What the part changed since its last commit: its kept front, and its
    // cut in progress or its held front.
    MtChangeReport since;
    bool changed = false;
    if (kept_ && kept_->record == part_->record) {
      since = kept_->changes;
      changed = true;
    }
    if (active_ && active_->record == part_->record) {
      since.append(active_->tx.changes);
      changed = true;
    } else if (held_) {
      since.append(held_->changes);
      changed = true;
    }
    for (auto& p : part_->record->validate(mt, changed ? &since : nullptr).problems) report.add("cutter: " + p);
  }
  if (frame_ && frame_->commit)
    for (auto& p : validate_retractable(mt, frame_->commit->changes, frame_->commit->fragments_before).problems)
      report.add("cutter: the frame's commit: " + p);
  for (auto& p : crack_.validate().problems) report.add("cutter: " + p);
  if (!active_) {  // between cuts: the cuts' storage is handed back clean
    for (auto& p : workspace_.validate().problems) report.add("cutter: " + p);
    return report;
  }
  const Active& a = *active_;
  for (auto& p : a.cut->validate(mt).problems) report.add(p);
  for (std::size_t i = 0; i < a.order.size(); ++i) {
    const bool done = a.cut->job_done(a.order[i]);
    if (done != (i < a.next)) report.add("cutter: job order entry " + std::to_string(i) + " done out of order");
  }
  if (a.cut->jobs_finished() != a.next) report.add("cutter: jobs done miscounted");
  return report;
}

}  // namespace mtcut::cut
