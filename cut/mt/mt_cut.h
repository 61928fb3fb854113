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
// not depend on the order of the jobs: the cut computes every split when it
// starts (keyed points, tet_splitter.h), and the first job appends all the
// new vertices at once in the order of their keys. One cut must finish
// before the next starts.

#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "cut/cut_polygon.h"
#include "cut/mt/fragment_decomposition.h"
#include "cut/mt/mt_change_report.h"
#include "cut/split_table.h"
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
};

// One cut in progress. Not copyable or movable: the classifier refers to the
// polygon and geometry it owns.
class MtCut {
 public:
  // Step 1: every live MT tet the polygon cuts (or that holds a vertex the
  // cut passes through, on its negative side), found through `bvh` (in step
  // with `mt`), and its split (from `table`, of def.scheme). `geometry`:
  // (mt.num_vertices()) positions the cut is computed on; empty = rest.
  MtCut(const Mt& mt, const TetBvh& bvh, const CutPolygon& polygon, std::vector<Vec3> geometry,
        const MtCutDef& def, SplitTable& table);
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
  // Tets found to cut or relabel; points the cut makes.
  std::size_t tets_to_change() const { return pending_.size(); }
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
    bool split = false;  // else relabel onto vertex copies
    bool done = false;
    KeyedSplit keyed;    // the split (split tets only)
  };
  void change_tet(Mt& mt, TetBvh& bvh, Pending& p, MtChangeReport& report);
  void add_vertices(Mt& mt, MtChangeReport& report);
  VertId vertex_of(const PointKey& key) const;
  std::size_t job_of(FragId f) const;

  CutPolygon polygon_;
  std::vector<Vec3> geometry_;  // (n_vertices at start) positions the cut is computed on
  MtCutDef def_;
  CutClassifier classifier_;
  std::vector<std::pair<PointKey, PointSource>> points_;            // new points, in key order
  std::unordered_map<PointKey, VertId, PointKeyHash> point_ids_;  // after add_vertices
  bool vertices_added_ = false;
  std::vector<Pending> pending_;                             // tets to change
  std::unordered_map<std::int32_t, std::int32_t> pending_of_;  // tet id -> index in pending_
  std::vector<FragId> jobs_;
  std::vector<std::vector<std::int32_t>> job_tets_;  // (jobs) pending tets the fragment creates
  std::vector<std::uint8_t> job_done_;
  std::size_t jobs_done_ = 0;
  double find_seconds_ = 0;
  DecompositionScratch scratch_;
  std::vector<TetId> pieces_;  // scratch
  // Scratch of change_tet, kept so that a split allocates nothing: the
  // pieces' vertices, the faces of the old tet each corner lies on, and the
  // pieces' sorted faces.
  std::vector<Tet> made_;
  std::vector<std::array<std::uint8_t, 4>> on_face_;
  std::vector<std::array<VertId, 3>> faces_;
};

// Order in which cut_mt processes the jobs (tests check they agree).
enum class JobOrder : std::uint8_t { kAscending, kDescending, kShuffled };

struct CutMtOptions {
  MtCutDef def;
  JobOrder order = JobOrder::kAscending;
  std::uint64_t seed = 1;  // for kShuffled
};

// The whole cut at once: step 1, then every job. `geometry` as for MtCut.
// `table` (of def.scheme) may be shared between cuts; nullptr uses a fresh one.
MtChangeReport cut_mt(engine::Mt& mt, TetBvh& bvh, const CutPolygon& polygon, std::vector<Vec3> geometry = {},
                      const CutMtOptions& options = {}, SplitTable* table = nullptr);

}  // namespace mtcut::cut
