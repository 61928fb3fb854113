#pragma once
// The time-critical cutter (paper, section 6; DESIGN.md "Time-critical
// cutter"): cuts queue up, each becomes fragment jobs (mt_cut.h), and every
// frame run(budget) does as many jobs as the budget allows, the fragments
// the current frontier shows first, the rest in later frames.
//
// Why the frontier is frozen, and how it follows. While a cut is half done
// the MT mixes split and unsplit tets, and only fragment sets whose
// fragments are all processed (or untouched) are conforming meshes; so the
// resolution may not change (frozen()) until every job is done. The set S
// itself must still follow the cut: when a fragment f in S falls into parts,
// every part must be in S (map_fragment_set), otherwise a part's children
// could be in S without their parent. With visible_at_once (default) the
// first call that reaches a cut's visible jobs does all of them, whatever the
// budget, so the mesh the World shows is, after every call, the frontier of
// the mapped S with the whole cut in it (all frontier tets the cut crosses
// are created by visible fragments). The World's step after each run():
//     report = cutter.run(mt, bvh, frontier, budget);
//     follow_cut(mt, frontier, report);  // = map_frontier(mt, frontier, report.fragment_splits)
//     carry state over the report (made vertices, replaced tets);
//     if (!cutter.frozen()) move the frontier (selective refinement).
//
// Provisional cuts. Progressive cutting (DESIGN.md, "Progressive cutting";
// cut_retraction.h, part_record.h) cuts a growing stroke's part every frame
// and takes the last frame's provisional cut back first (of a part's front,
// what the grown polygon changes: recut()): submit_provisional()
// queues a cut that is held, once started, with everything it changed, until
// retract() undoes it (the MT as before it, up to numbering). At most one is
// held, and it is the last cut: retract() before submitting anything else.
// recut() does a stroke's frame: a part with a fixed plane commits what it
// crosses completely and holds only its front provisionally.
//
// Every cut is a transaction: when its last job is done, check_cut
// (cut_guard.h) looks where it met older cracks, and a cut that would leave
// the MT invalid is taken back and reported (RunResult::refused). A part's
// frame is one too: its commit is checked with its front (the commit owes
// the fragments what the front splits, fragment_ledger.h), so a refused
// front takes the frame's commit back, and a refused commit or front queues
// the last frame's front again, which the caller runs after mapping the
// refusal (the MT as the last frame left it); a part's end refused is cut
// again with the part's polygon of its last frame, which its front's guard
// kept (the commits owe the fragments what the end splits).
//
// Budgets are work units (tets split or relabelled, plus one per job: the
// same on every machine, so runs are reproducible) and/or milliseconds;
// every call does at least one job when any is pending. A part's frame
// (its commit and its front) is cut whole in the call that reaches it,
// whatever the budget (run()): the budget spreads cuts for good and the
// provisional cut of a part with no record.

#include <array>
#include <cstdint>
#include <deque>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "cut/mt/cut_retraction.h"
#include "cut/mt/follow_cut.h"
#include "cut/mt/mt_cut.h"
#include "cut/mt/mt_pieces.h"
#include "cut/mt/part_record.h"
#include "cut/mt/stroke_crack.h"
#include "engine/mt/frontier.h"

namespace mtcut::cut {

using engine::Frontier;

struct CutBudget {
  std::size_t work = std::numeric_limits<std::size_t>::max();  // work units (see above)
  double milliseconds = std::numeric_limits<double>::infinity();
  static CutBudget unlimited() { return {}; }
  static CutBudget units(std::size_t w) { return {w, std::numeric_limits<double>::infinity()}; }
  static CutBudget ms(double m) { return {std::numeric_limits<std::size_t>::max(), m}; }
};

struct TimeCriticalCutterDef {
  MtCutDef cut;
  bool visible_at_once = true;  // a call that starts a cut's visible jobs finishes them
  bool report_pieces = true;    // count_pieces() when a cut completes (costs a pass over the MT)
};

struct CutterProgress {
  std::size_t cuts_queued = 0;       // cuts not finished, the active one included
  std::size_t jobs_done = 0;         // of the active cut
  std::size_t jobs_pending = 0;      // of the active cut (queued cuts are not searched yet)
  std::size_t visible_pending = 0;   // of the active cut
  std::size_t cuts_finished = 0;     // since construction
  std::size_t total_jobs_done = 0;   // since construction
  double seconds = 0;                // spent in run() since construction
};

class TimeCriticalCutter {
 public:
  explicit TimeCriticalCutter(const TimeCriticalCutterDef& def = {});

  // Queues a cut behind the others (std::logic_error while a provisional
  // cut is held). `geometry`: positions of the MT's
  // current vertices the cut is computed on (deformed), empty = rest
  // positions when the cut starts. Vertices made before it starts get theirs
  // from their parents.
  void submit(const Mt& mt, const CutPolygon& polygon, std::vector<Vec3> geometry = {});
  // Queues a provisional cut (in rest space), to be taken back by retract().
  // Throws std::logic_error while one is held.
  void submit_provisional(const CutPolygon& polygon);
  // A provisional cut is queued, in progress or done and not retracted
  // (a part's front kept from earlier frames among them).
  bool provisional_held() const { return provisional_pending() || kept_; }
  // Takes the provisional cut back: a queued one is dropped, a started one
  // (its pending jobs dropped) is undone in `mt` and `bvh`. nullopt when none
  // had started. The caller maps its frontier (follow_retraction).
  std::optional<CutRetraction> retract(Mt& mt, TetBvh& bvh);
  // A stroke's frame (cut/stroke_sweep.h), all in rest space: retract(),
  // then queue `ended` (the parts that ended) for good and `current` (the
  // part in progress) progressively. The part in progress keeps a record
  // (part_record.h) from the first frame its plane is fixed (`plane_fixed`:
  // StrokeSweep::plane_fixed()): each frame its tets crossed completely are
  // committed, the rest (the front) split provisionally, and the part's end
  // takes every tet left. The front's splits that the grown polygon leaves
  // in the configuration they were made from stay (kept_front_splits: most
  // of them, the blade moving less than a tet a frame), held in the record;
  // only the others are taken back, and split afresh by the frame's commit
  // or front; where the part has met an older crack, the kept splits and
  // the new ones together pay its commits' ledger (cut_guard.h). Until the
  // plane is fixed the whole polygon is cut provisionally (again each
  // frame it moved by kRedoReach). A polygon of the part that is not on
  // the record's plane (the World carries each frame's polygon to rest
  // space anew) is projected onto it, joined with the part's last polygon.
  // Turns. Where the stroke turns gently (less than kMaxContinuedTurn), the
  // next part starts on the ended polygon's edge nearest it (the blade where
  // it turned) and pivots about it: its polygons hold that edge exactly and
  // nothing behind it, and its cuts continue the stroke's crack across it
  // (stroke_crack.h: what the crack made behind is sided by it, its front
  // on the edge is split), so the two parts' cracks are one surface and the
  // tissue they go round comes apart. Two parts that each cut the tets at
  // the turn partially would leave a bridge there. A sharper turn starts a
  // new crack, and so does a turn back (`turned_back`, per ended part:
  // StrokeAdvance; a V's planes are under kMaxContinuedTurn apart, but the
  // next part lies behind the edge, not across it) and a turn where an end
  // of the blade lies inside the tissue: there the old crack's end would
  // meet the new sheet at a corner inside the tissue, and a coarse tet
  // around that corner, its vertices sided by the nearer of two planes,
  // would hold both sheets on one edge (a pinch at a resolution between the
  // finest and the coarsest). The two cracks cross: the ended polygon goes on past the
  // turn's edge, and the next part's polygons start behind it, each by
  // kCrossingReach of how far past the edge the tets reach that it passes
  // through (every resolution), so the tissue a sharp turn goes round comes
  // apart too, with a short stub of each crack beyond the other. Returns the
  // retraction.
  std::optional<CutRetraction> recut(Mt& mt, TetBvh& bvh, std::span<const CutPolygon> ended,
                                     std::span<const std::uint8_t> turned_back,
                                     const std::optional<CutPolygon>& current, bool plane_fixed);
  static constexpr double kMaxContinuedTurn = 45.0;  // degrees between two parts' planes
  // A part cut whole each frame (its plane not fixed yet, or pivoting about
  // a turn's edge) is cut again only once its polygon lies farther from the
  // one cut than this share of the mean edge of the finest tets that cut
  // split (a frame of a 1 kHz stylus moves the blade a few hundredths of a
  // tet): till then the incision shown lags the blade by less than that.
  // The part's end, and the first frame of its fixed plane, cut exactly.
  static constexpr double kRedoReach = 0.25;
  // Of the reach of the tets at a sharp turn (above). Less leaves bridges of
  // tets that both cracks cut partially; more makes stubs that cut off a
  // piece against the object's side or the other stub: in random corner
  // cuts, 0.3, 0.5 and 0.6 left more corners on (docs/progressive_cutting.md).
  static constexpr double kCrossingReach = 0.4;
  // The record of the part in progress (nullptr when none).
  const PartRecord* part_record() const { return part_ ? part_->record.get() : nullptr; }

  // What the held provisional cut has changed so far (nullptr when none).
  const MtChangeReport* provisional_changes() const;

  // Processes jobs within `budget`, visible fragments of `frontier` first
  // (frontier: the World's, mapped after every call). Returns what changed;
  // `pieces` is filled when the call finished a cut, def.report_pieces and
  // the pieces may have changed since they were last counted or the cutter
  // was made (a fragment split, or a retraction that merged parts: the
  // caller counts the MT's pieces before its first cut), except while a part's crack
  // has a front inside the tissue: its pieces are counted when a commit
  // leaves no front, or at the part's end.
  struct RunResult {
    MtChangeReport changes;          // of the cuts kept (and of the one in progress)
    std::size_t cuts_finished = 0;   // kept or refused
    std::optional<std::size_t> pieces;  // how many, after the last cut this call finished (count_pieces)
    // A cut that check_cut (cut_guard.h) refused when it finished, taken
    // back: the call stops there, and the caller maps its frontier through
    // the retraction (follow_retraction) after following `changes`.
    std::optional<CutRetraction> refused;
    // Vertices of the refused cut that earlier calls reported, and of a
    // part's commit taken back with it (TimeCriticalCutter) that a call
    // reported before this one.
    std::size_t refused_reported_vertices = 0;
  };
  RunResult run(Mt& mt, TetBvh& bvh, const Frontier& frontier, const CutBudget& budget);

  bool frozen() const { return active_.has_value() || !queue_.empty(); }
  // Reclaiming the slots of retracted cuts. A retracted cut leaves its
  // pieces as dead tets and its vertices unused (cut_retraction.h), so a
  // stroke cut progressively leaves about its part's cut every frame: a
  // thousand steps through the builtin organ left four million tet slots
  // for 23,000 live tets. When no cut is queued or in progress and the dead
  // tets that no held provisional cut needs back outnumber the live ones (at
  // least kReclaimMin of them), this compacts the MT (Mt::compact: the
  // vertices made before the first cut keep their ids), renumbers the held
  // cut and `bvh` (TetBvh::renumber); the caller maps what else it holds through the
  // result (a frontier: Frontier::from_fragments over the same fragments).
  // nullopt when it did nothing. Amortised, a pass over the MT per as many
  // dead tets as there are live ones. The tets that the held cut and a
  // frame's kept commit split stay, dead, to be revived.
  static constexpr std::size_t kReclaimMin = 4096;
  // Room for progressive cutting, made before the first stroke (at setup,
  // not in a frame): the MT's arrays and this cutter's per-vertex and
  // per-tet storage sized to kRoom times the MT's vertices and tets (live
  // tets, as many dead ones before a reclaim, and what the stroke adds),
  // so that no step of a stroke copies them to grow them (a copy of the
  // liver's MT was a millisecond step). A larger MT later grows them as
  // before. The MT's contents do not change.
  void reserve(Mt& mt);
  static constexpr double kRoom = 3.0;
  bool reclaimable(const Mt& mt) const;  // reclaim() would compact now
  std::optional<engine::Mt::Compaction> reclaim(Mt& mt, TetBvh& bvh);
  CutterProgress progress() const;
  std::size_t cuts_refused() const { return refused_; }
  // The active cut's bookkeeping (MtCut::validate) and the job order:
  // no hidden job done while a visible one is pending; a held provisional
  // cut can be retracted (validate_retractable); between cuts, the cuts'
  // storage is clean (MtCutWorkspace::validate).
  engine::ValidationReport validate(const Mt& mt) const;

 private:
  // Filled by designated initialisers: a member left out keeps its default.
  struct Queued {
    CutPolygon polygon;
    std::vector<Vec3> geometry{};  // empty = rest
    bool provisional = false;
    std::shared_ptr<PartRecord> record{};  // a part's cut (part_record.h), with `select`
    CutSelect select = CutSelect::kAll;
    // A part's commit or end: its polygon of the last frame, which the cut
    // searches only outside of, beside the front (nullopt: search it all).
    std::optional<CutPolygon> grown_from{};
    // A polygon of the stroke in progress: cut as a continuation of the
    // stroke's crack where it starts on it (stroke_crack.h), and, for good,
    // recorded in it. `leading`: its outline edge that the next polygon
    // starts on.
    bool stroke = false;
    std::optional<std::array<Vec3, 2>> leading{};
    // A part's end: its polygon of the last frame, cut instead should the
    // end be refused (its commits owe the fragments what the end splits):
    // first as an end, then, should that be refused too, as the last
    // frame's front was cut, for good (`select` kFront, not provisional: it
    // decomposes no fragment, so the tissue there stays joined).
    std::optional<CutPolygon> fallback{};
    bool is_fallback = false;  // this is that first fallback
    bool whole_part = false;   // a part's polygon cut whole, provisionally (kRedoReach)
  };
  // Where a stroke's polygon goes on from the one before it across a gentle
  // turn: the earlier polygon's outline edge (a, b) that the next starts on,
  // the earlier one's direction across it (in its plane, away from it) and
  // its normal.
  struct Pivot {
    Vec3 a, b, forward, normal;
  };
  // The part in progress: its record and its last polygon (on its plane).
  struct Part {
    std::shared_ptr<PartRecord> record;
    CutPolygon last;
  };
  // Queues `q` as the provisional cut (std::logic_error while one is held).
  void queue_provisional(Queued q);
  // Queues a stroke's polygon for good (`record`: its part's, if any, and
  // `fallback` its polygon of the last frame).
  void submit_ended(const CutPolygon& polygon, std::shared_ptr<PartRecord> record, const std::optional<Pivot>& next,
                    std::optional<CutPolygon> fallback = std::nullopt);
  // The polygon of `corners` that starts on the pivot's edge: the hull of
  // the edge and the corners ahead of it, on the plane through the edge
  // that fits those corners best; nullopt when none lies ahead.
  static std::optional<CutPolygon> pivoted(const Pivot& pivot, const std::vector<Vec3>& corners);
  // Queues the part's frame: its committed tets, then its front
  // provisionally.
  void submit_part(const Part& part, std::optional<CutPolygon> grown_from = std::nullopt);
  // Takes off the queue a frame of the part that `record` keeps, left
  // there by a budget that an earlier cut spent (retract() dropped its
  // front): run later, its commit would be kept with no front to check it
  // and make the mesh conform (run()). `grown_from` receives the polygon
  // it grew from (none: the part's first frame); untouched when no frame
  // of the part is queued.
  void drop_queued_frame(const PartRecord& record, std::optional<CutPolygon>& grown_from);
  // Where the stroke turns sharply from `polygon` to `next`: crossing_ set
  // for the next part, and `polygon` taken past the turn's edge (nullopt:
  // no edge of it lies where `next` starts).
  std::optional<CutPolygon> cross_at_turn(const Mt& mt, const TetBvh& bvh, const CutPolygon& polygon,
                                          const CutPolygon& next);
  // The Hausdorff distance between two convex polygons.
  static double hausdorff(const CutPolygon& a, const CutPolygon& b);
  // The polygon of the part in progress, `current`, when it is cut whole:
  // pivoted about the last turn's edge, or starting behind a sharp turn's.
  CutPolygon whole_polygon(const CutPolygon& current) const;
  // The pivot where `next` goes on from `previous` across a gentle turn, if it does.
  static std::optional<Pivot> pivot_between(const CutPolygon& previous, const CutPolygon& next);
  // The edge of `previous` where `next` goes on from it (the blade where
  // the stroke turned), if there is one within reach.
  static std::optional<Pivot> turn_edge(const CutPolygon& previous, const CutPolygon& next);
  // Where a sharp turn's two cracks cross: the turn's edge (a, b) and how
  // far behind it the next part's polygons start.
  struct Crossing {
    Vec3 a, b;
    double reach = 0;
  };
  // `polygon` grown across the crossing's edge, out of it in its plane, by
  // the crossing's reach.
  static CutPolygon past(const CutPolygon& polygon, const Crossing& crossing);
  // `polygon` on the part's plane, as the hull of it and the part's last
  // polygon unless it is of that plane already and covers the last one
  // (nullopt when it has no area there).
  std::optional<CutPolygon> on_part_plane(const Part& part, const CutPolygon& polygon) const;
  // What a cut changed since it started, to take it back: the MT's fragment
  // count and the index when it started, and every change it made.
  // A reclaim() while it is held renumbers its changes; should the index
  // lose its mark then, it is retracted tet by tet.
  struct Transaction {
    std::size_t fragments_before = 0;
    std::size_t first_new_vertex = 0;
    MtChangeReport changes;
    std::optional<engine::TetBvh::Mark> bvh_mark;
    // A part's front (its record) ...
    std::shared_ptr<PartRecord> front_of{};
    // ... holding splits kept from earlier frames: taken back tet by tet
    // (retract_replacements), with no mark and no fragment count.
    bool combined = false;
    // A part cut whole (recut): its polygon, and how far the part's next
    // polygons may lie from it before the cut is redone (kRedoReach of the
    // tets it split).
    std::optional<CutPolygon> whole_part{};
    double redo_within = 0;
  };
  struct Active {
    std::unique_ptr<MtCut> cut;
    bool provisional = false;
    std::shared_ptr<PartRecord> record;  // the committed cut of a part joins it when kept
    CutSelect select = CutSelect::kAll;
    bool split_every_level = false;  // split a tet born of the root and replaced by the drain
    std::optional<CutPolygon> crack_polygon;  // a stroke's cut for good: recorded in its crack when kept
    std::optional<CutPolygon> whole_part;     // a part cut whole, provisionally (Transaction::whole_part)
    Transaction tx;
    std::vector<std::size_t> order;   // jobs: visible first, then hidden, ascending within each
    std::size_t visible = 0;          // leading entries of `order` that are visible
    std::size_t next = 0;             // next entry of `order`
    bool reported_before = false;     // an earlier call reported some of its changes
    std::optional<CutPolygon> fallback;  // Queued::fallback
    bool is_fallback = false;
  };
  void start_next(const Mt& mt, TetBvh& bvh, const Frontier& frontier);
  void extend_geometry(std::span<const MadeVertex> made);

  TimeCriticalCutterDef def_;
  SplitTable table_;
  MtCutWorkspace workspace_;  // reused by each cut in turn
  std::deque<Queued> queue_;
  std::optional<Active> active_;
  std::optional<Transaction> held_;  // the provisional cut, finished and kept until retract()
  // The splits of the part's front kept this frame (recut), held in its
  // record, until the frame's front joins them in held_.
  struct Kept {
    std::shared_ptr<PartRecord> record;
    MtChangeReport changes;
  };
  std::optional<Kept> kept_;
  // The part whose front balances its ledger (cut_guard.h: what its
  // commits owe plus its whole front's chain is zero on every face): its
  // last front's check passed, against the ledger, and since then only a
  // frame's keep_front took splits of that front back, their chain held
  // negated in `taken` until the frame's front is checked. That check then
  // sums what the frame changed, not the whole front with the ledger
  // (check_cut's `taken`).
  struct Balanced {
    std::shared_ptr<PartRecord> record;
    std::optional<FragmentLedger> taken{};
  };
  std::optional<Balanced> balanced_;
  // A provisional cut is queued, in progress or held (not counting kept_).
  bool provisional_pending() const { return provisional_queued_ || held_ || (active_ && active_->provisional); }
  // The part's front under its grown `polygon` (recut): the splits it
  // changes taken back, the others kept (kept_). nullopt when nothing was
  // held.
  std::optional<CutRetraction> keep_front(Mt& mt, TetBvh& bvh, const CutPolygon& polygon);
  // Takes `tx` back (a part's front of `record`, or any provisional cut).
  CutRetraction take_back(Mt& mt, TetBvh& bvh, Transaction& tx);
  // A commit decomposed the fragments of `held`'s pieces, or was taken
  // back: its replacements name the fragments the pieces are in now.
  static void follow_fragments(const Mt& mt, MtChangeReport& held);
  // Drops from `retraction.unused` the points `record` committed since
  // they were made (a commit's pieces use them).
  static void keep_committed(CutRetraction& retraction, const PartRecord* record);
  std::size_t first_cut_vertex_ = SIZE_MAX;  // the MT's vertex count when the first cut started
  bool provisional_queued_ = false;  // the queue's last entry is provisional
  std::optional<Part> part_;         // the part in progress, once its plane is fixed
  // What a part's commit found, for the front queued behind it: kept only
  // until the next cut starts, and used only if the MT is still the same
  // one at `revision`.
  struct Searched {
    const PartRecord* record = nullptr;
    std::uint64_t instance = 0, revision = 0;
    std::vector<TetId> tets;
  };
  std::optional<Searched> searched_;
  // The frame of the part in progress, from its commit's start to its
  // front's end: what the record was before the commit, so that a refused
  // commit or front takes the frame back whole (the commit retracted, the
  // record as before it, the last frame's polygon cut again as the front:
  // the MT as the last frame left it, up to numbering).
  struct Frame {  // filled by designated initialisers
    const PartRecord* record = nullptr;
    std::optional<CutPolygon> previous{};  // the part's polygon of the last frame (none: its first)
    PartRecord::Before before{};           // the record before the commit
    std::optional<Transaction> commit{};   // the commit, once kept
    // Where the commit's changes start in the report of the call that kept
    // it (`call`), when that call reported all of them.
    std::optional<MtChangeReport::Length> reported_from{};
    std::uint64_t call = 0;
  };
  std::optional<Frame> frame_;
  std::uint64_t calls_ = 0;  // run() calls so far
  // Takes the frame of `record` back after its commit or front (`select`)
  // was refused (result.refused holds that cut's retraction).
  void take_back_frame(Mt& mt, TetBvh& bvh, const std::shared_ptr<PartRecord>& record, CutSelect select,
                       RunResult& result);
  // The stroke's crack (stroke_crack.h): what its cuts for good made, so that
  // a part going on from the last across a gentle turn continues it.
  StrokeCrack crack_;
  std::optional<Pivot> pivot_;  // the last ended polygon's, when the stroke goes on from it
  std::optional<Crossing> crossing_;  // the last sharp turn's, while the part after it is cut
  // A fragment split or a retraction merged parts since pieces were last
  // counted (or since the cutter was made: the caller counts the MT's
  // pieces before its first cut): the next finished cut counts them (else it
  // reports none). A cut that changes nothing, a blade still outside the
  // tissue, costs no pass over the MT.
  bool pieces_stale_ = false;
  CutterProgress totals_;
  std::size_t refused_ = 0;
};

}  // namespace mtcut::cut
