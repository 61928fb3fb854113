#pragma once
// Cutting the MT at every resolution (paper, section 4; DESIGN.md "Cutting"):
// one cut polygon, found in every fragment, each cut tet replaced by its LUT
// split R(t), and the DAG updated fragment by fragment.
//
// Why a cut is a set of fragment jobs. The paper's DAG update is local to a
// fragment and order-free; the time-critical cutter (time_critical_cutter.h)
// must run the visible fragments first and spread the rest over frames. So
// the search (step 1) runs once, when the cut starts, and groups the tets to
// change by the fragment that creates them: a job. A job for f splits the
// still-unsplit tets that f creates or replaces (the split of a tet is a
// pure function of its vertices, tet_splitter.h, so it does not matter which
// job does it first), then decomposes f (fragment_decomposition.h). Every job
// sees both tessellations of its region final, so any order of jobs gives
// the same MT up to the numbering of new vertices and fragments.
//
// Which geometry is cut. `geometry` holds the position of every MT vertex the
// cut is computed on: the deformed positions when the tissue is deformed,
// else the rest positions. Exact decisions and edge parameters come from it;
// each new vertex's rest position is the same weighted sum of its parents'
// rest positions (the same edge parameter), so every resolution and both
// spaces agree. Pieces of a positive tet are positive in rest space whatever
// the deformation, since the split's orientation depends only on the weights.
//
// Snapping. MtCutDef::snap defaults to 0 (the classifier's floor, 1e-6 of an
// edge): a vertex snapped onto the cut bends the cut surface through it, but
// only in the tessellations that hold that vertex, so the parts of a fragment
// would no longer cover the same region in its created and replaced
// tessellations. A planar cut surface is the same in every resolution.
//
// Vertex ids. The LUT chooses quad diagonals by global vertex id, so ids must
// not depend on the order of the jobs, even through later cuts (tet ids do):
// the cut resolves every split to vertex ids when it starts (keyed points,
// tet_splitter.h, numbered in key order), and the first job appends all the
// new vertices at once. One cut must finish before the next starts, and
// nothing else may add MT vertices meanwhile.
//
// Why the splits are resolved up front. A split is a recipe of local labels;
// resolving a label is a hash lookup of its key. Doing it once per label and
// tet when the cut starts, into a flat array of pieces, leaves each job only
// appending tets (the boundary mask of a piece comes from the recipe,
// recipe_faces.h), so the cost of a job is what the MT and the BVH edits cost.

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "absl/container/flat_hash_map.h"
#include "cut/cut_polygon.h"
#include "cut/lut/split_table.h"
#include "cut/mt/fragment_decomposition.h"
#include "cut/mt/mt_change_report.h"
#include "cut/mt/mt_cut_workspace.h"
#include "cut/mt/part_record.h"
#include "cut/tet_classifier.h"
#include "cut/tet_splitter.h"
#include "cut/vertex_factory.h"
#include "engine/mt/tet_bvh.h"
#include "engine/validation.h"

namespace mtcut::cut {

using engine::TetBvh;

struct MtCutDef {
  SplitScheme scheme = SplitScheme::kLut;
  double snap = 0.0;  // classifier snap, fraction of an edge (see "Snapping" above)
  // The polygon continues the previous cut of a stroke (stroke_junction.h);
  // read only while the cut is searched (MtCut's constructor).
  const CutContinuation* continuation = nullptr;
  // A part cut progressively (part_record.h): its committed pieces are not
  // searched, its committed points are taken again and their edges count as
  // crossed, the vertices of its pieces are kept off the cut; `select` says
  // which found tets change. Read while the cut is searched.
  const PartRecord* record = nullptr;
  CutSelect select = CutSelect::kAll;
  // Every tet the cut may change lies in the box `search` (grown by the
  // snap reach like the polygon's), or, when `grown_from` is given too,
  // within the snap reach of where the polygon covers what `grown_from` (a
  // polygon of the same plane) does not (CutPolygon::box_beyond): a part's
  // frame searches only around its front and where its polygon grew, and
  // walks none of the index's nodes that lie behind it or along the outline
  // the two polygons share (the last frame's front split the tets there:
  // its record holds them, or they were taken back and lie in `search`).
  // Read while the cut is searched.
  const engine::Aabb* search = nullptr;
  const CutPolygon* grown_from = nullptr;
  // The tets the search takes instead of walking the index (neither walk
  // above is made): those the last cut of the same polygon found
  // (candidates()), when nothing but that cut has edited the MT since and
  // every tet this cut may change is among them (a part's front after its
  // commit: a tet the outline passes through lies where the polygon grew
  // or in the commit's `search`, so the commit found it, or its record
  // holds it; and the tets the commit made are its record's). The dead and
  // those off the search box are passed over. Read while the cut is
  // searched.
  const std::vector<TetId>* candidates = nullptr;
  // Step 3 (UpdateProcessFragment): the fragments the cut separates are
  // decomposed. Off for a provisional cut, which the next frame takes back
  // (a stroke's part in progress): it separates nothing until the cut for
  // good, and a decomposition would cost the guard a check of each part
  // whole (cut_guard.h) every frame.
  bool decompose = true;
  // A narrowed search (`search`, `grown_from` or `candidates`) is checked
  // against a walk of the whole polygon: the cut must change the same tets
  // the same way (split by the same configuration, or relabelled), else the
  // constructor throws std::logic_error. It searches and classifies twice;
  // the tests of strokes turn it on.
  bool check_search = false;
};

// One cut in progress. Not copyable: it holds its workspace (its own, or one
// lent by the caller for reuse) until it is destroyed.
class MtCut {
 public:
  // Step 1: every live MT tet the polygon cuts (or that holds a vertex the
  // cut passes through, on its negative side), found through `bvh` (in step
  // with `mt`), and its split (from `table`, of def.scheme). `geometry`:
  // (mt.num_vertices()) positions the cut is computed on; empty = rest.
  // `workspace`: storage reused from earlier cuts, held until the cut is
  // destroyed (nullptr: the cut allocates its own, a pass over the vertices).
  MtCut(const Mt& mt, const TetBvh& bvh, const CutPolygon& polygon, std::span<const Vec3> geometry,
        const MtCutDef& def, SplitTable& table, MtCutWorkspace* workspace = nullptr);
  ~MtCut();  // hands the workspace back clean
  MtCut(const MtCut&) = delete;
  MtCut& operator=(const MtCut&) = delete;

  // The fragments with work, in ascending id order.
  std::span<const FragId> jobs() const { return jobs_; }
  bool job_done(std::size_t job) const { return job_done_[job] != 0; }
  // Tets the job will still split or relabel (0 once done or when another
  // job did them), plus one for the decomposition.
  std::size_t job_cost(const Mt& mt, std::size_t job) const;
  std::size_t jobs_pending() const { return jobs_.size() - jobs_done_; }
  std::size_t jobs_finished() const { return jobs_done_; }
  bool done() const { return jobs_done_ == jobs_.size(); }
  // Tets found to cut or relabel (of those, the ones `select` left whole);
  // points the cut makes.
  std::size_t tets_to_change() const { return pending_.size(); }
  std::size_t tets_left_whole() const { return left_whole_; }
  // Some tet to cut or relabel is a piece of an earlier cut (Mt::error_inherited).
  bool changes_earlier_pieces(const Mt& mt) const;
  // Tets found to split and not crossed completely (the polygon's outline
  // passes through them, or a vertex lies on its plane), whatever
  // `select`: the crack's front in the tissue.
  std::size_t tets_crossed_partially() const { return crossed_partially_; }
  // The box of the tets left whole (in the cut's geometry; empty when none).
  const engine::Aabb& left_whole_box() const { return left_whole_box_; }
  // Every tet the search found that the polygon may cut, ascending
  // (MtCutDef::candidates of a later cut).
  const std::vector<TetId>& candidates() const { return candidates_; }
  std::size_t points_to_make() const { return points_.size(); }
  // Time of step 1.
  double find_seconds() const { return find_seconds_; }

  // Processes job `job` (steps 2 and 3 for its fragment); appends what
  // changed to `report`. The first call also appends every new vertex.
  void process(Mt& mt, TetBvh& bvh, std::size_t job, MtChangeReport& report);

  // Pending tets are alive and unchanged, done ones dead; the job bookkeeping adds up.
  engine::ValidationReport validate(const Mt& mt) const;

 private:
  struct Pending {
    TetId tet;
    std::uint32_t first = 0;             // its pieces in piece_tets_
    std::uint8_t count = 0;              // number of pieces (1 for a relabel)
    std::uint8_t on_faces = 0;           // relabel: faces lying in the cut (all vertices on it)
    bool split = false;                  // else relabel onto vertex copies
    std::uint32_t config = 0;            // split tets: TetConfig::key
    bool done = false;
    const SplitRecipe* recipe = nullptr; // split tets: the pieces' faces
  };
  // Step 1, after the polygon's box: the tets around every vertex the
  // candidates put on the cut, as candidates too, round after round.
  // MtCutDef::check_search: this cut against the one of the same polygon
  // with no narrowed search.
  void check_search(const Mt& mt, const TetBvh& bvh, std::span<const Vec3> geometry, SplitTable& table) const;
  static void add_tets_around_on_vertices(const Mt& mt, const TetBvh& bvh, CutClassifier& classifier,
                                          const PartRecord* record, std::vector<TetId>& found);
  // The cut passes through v and splits it (it separates some tets from
  // others); while the cut is searched.
  bool splits(VertId v) const { return workspace_->separating[v.index()] != 0; }
  void change_tet(Mt& mt, TetBvh& bvh, Pending& p, MtChangeReport& report);
  void add_vertices(Mt& mt, MtChangeReport& report);
  // The vertex of `key`, numbered (its position and parents recorded from
  // `source()`, a MadeVertex) when the cut first meets it;
  // number_points_by_key() renumbers.
  template <class Source>
  VertId point_id(const PointKey& key, Source&& source);
  // The vertex of a point on straddling edge number `edge` (the
  // classifier's), on the side of `label`: as point_id, without a map.
  template <class Source>
  VertId edge_point_id(std::int32_t edge, const Tet& tet, Label label, Source&& source);
  void resolve_split(Pending& p, const Tet& tet, const TetConfig& config,
                     const std::array<std::int32_t, 6>& edge_numbers, const CutClassifier& classifier,
                     SplitTable& table);
  void resolve_relabel(Pending& p, const Tet& tet, const CutClassifier& classifier);
  // Renumbers the new points in key order (point_order_, and the ids in piece_tets_).
  void number_points_by_key();
  // Index in pending_ of tet t, -1 when t is not pending (the workspace's
  // array, over the tets that existed when the cut started).
  std::int32_t pending_index(TetId t) const {
    const std::vector<std::int32_t>& of = workspace_->pending_of;
    return t.index() < of.size() ? of[t.index()] : -1;
  }
  std::span<const std::int32_t> job_tets(std::size_t job) const {
    return std::span<const std::int32_t>(job_tets_).subspan(job_first_[job], job_first_[job + 1] - job_first_[job]);
  }

  CutPolygon polygon_;
  MtCutDef def_;
  std::unique_ptr<MtCutWorkspace> own_workspace_;  // when none was given
  MtCutWorkspace* workspace_;
  std::size_t first_vertex_ = 0;  // id of the first new vertex (the MT's vertex count at start)
  std::vector<MadeVertex> points_;  // new points, in the order the scan met them (ids and rest unset)
  std::vector<std::int32_t> point_order_;  // indices in points_ in id (key) order
  absl::flat_hash_map<PointKey, std::int32_t, PointKeyHash> point_index_;  // key -> index in points_
  // Points on straddling edges (most of them), index in points_ by 3 x the
  // classifier's edge number + the label's side; -1 = not met yet.
  std::vector<std::int32_t> edge_point_;
  bool vertices_added_ = false;
  std::vector<Pending> pending_;    // tets to change, in the search's order
  std::vector<Tet> piece_tets_;     // the pieces of every pending tet, final vertex ids
  std::size_t new_tets_ = 0;        // pieces of split tets
  std::size_t left_whole_ = 0;      // found to change, not of `select`
  std::size_t crossed_partially_ = 0;
  engine::Aabb left_whole_box_;
  std::vector<TetId> candidates_;
  std::vector<FragId> jobs_;
  std::vector<std::uint32_t> job_first_;  // (jobs + 1) offsets into job_tets_
  std::vector<std::int32_t> job_tets_;    // pending tets each job's fragment creates
  std::vector<std::uint8_t> job_done_;
  std::size_t jobs_done_ = 0;
  double find_seconds_ = 0;
  std::vector<TetId> pieces_;                // scratch of change_tet
  std::vector<engine::FaceMask> piece_masks_;  // scratch of change_tet
  std::vector<std::int32_t> from_parents_;   // scratch of process
};

// Which splits of a part's front (`front`: provisional, cut under an
// earlier polygon of the part, part_record.h) the part's grown `polygon`
// leaves as they are: the tet is still crossed partially, in the
// configuration it was split from (TetConfig::key, with the record's
// points covering their edges as a cut of the part counts them), and none
// of its vertices lies within `reach` of the plane (the state of such a
// vertex is decided over all of a cut's tets, tet_classifier.h). The same
// configuration gives the same split up to where the outline crosses the
// tet's faces: a kept split's face points stay where the blade crossed
// them then, less than a tet behind it, and the tets split afresh beside
// it take them by key. `snap`: the cuts' (MtCutDef::snap). One flag per
// replacement; relabels are not kept.
std::vector<std::uint8_t> kept_front_splits(const Mt& mt, const MtChangeReport& front, const CutPolygon& polygon,
                                            const PartRecord& record, double snap, double reach,
                                            CutClassifier::Scratch* scratch = nullptr);

// Order in which cut_mt processes the jobs (tests check they agree).
enum class JobOrder : std::uint8_t { kAscending, kDescending, kShuffled };

struct CutMtOptions {
  MtCutDef def;
  JobOrder order = JobOrder::kAscending;
  std::uint64_t seed = 1;  // for kShuffled
};

// The whole cut at once: step 1, then every job. `geometry` and
// `workspace` as for MtCut. `table` (of def.scheme) may be shared between
// cuts; nullptr uses a fresh one.
MtChangeReport cut_mt(engine::Mt& mt, TetBvh& bvh, const CutPolygon& polygon, std::span<const Vec3> geometry = {},
                      const CutMtOptions& options = {}, SplitTable* table = nullptr,
                      MtCutWorkspace* workspace = nullptr);

}  // namespace mtcut::cut
