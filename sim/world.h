#pragma once
// The simulator: the frame loop of DESIGN.md over one organ.
//
// Why this shape. The World owns the multiresolution model (MT), the
// frontier in use, the spring model built on it and its state, and the
// scalpel. step() runs the frame as named stages, each timed:
//   1. scalpel   take the frame's poses: every sample of the blade since the
//                last frame, in time order (a fast stroke is a polyline of
//                poses, not one jump), the last one the frame's pose;
//   2. cut       extend the engaged blade's stroke by the poses; a straight
//                part of it that ended (the blade turned or left) is cut
//                for good, and the part in progress is cut provisionally:
//                every frame its blade moves, the last frame's provisional
//                cut is taken back (of a part's front, the splits the grown
//                polygon changes) and the part's polygon so far cut afresh
//                (cut/mt/cut_retraction.h says why), so the incision opens
//                behind the blade in the frame it passes. Polygons go from
//                the deformed tissue to rest space (rest_space_cut.h says
//                why); the time-critical cutter runs within its budget (a
//                part's frame, its commit and front, whole: the mesh shown
//                conforms in every frame, TimeCriticalCutter::run), the
//                frontier follows the fragments it split and, when its tets
//                changed, the springs on it start building (taken in stage
//                3, the state carried over, cut vertices from their parents
//                or from the last provisional cut's vertex of the same key);
//                a piece the cut separates has no spring left to the rest
//                and falls; a cut the cutter refuses (it would have pinched
//                the MT against an older crack, cut/mt/cut_guard.h) is
//                taken back and counted;
//   3. lod       unless the cutter froze it, take the frontier move decided
//                def.lod.build_frames ago, with its springs (built
//                meanwhile, sim/model_build.h), and carry the state over;
//                then, with no move pending, decide the next one toward the
//                error field around the blade (incrementally) and start
//                building its springs. A move takes effect build_frames
//                after the blade asked for it, and those frames' physics
//                overlaps its build. A cut takes any pending move first, so
//                the MT never changes under one, and its own springs build
//                while this stage decides the next move; they are taken
//                before it starts that move's build;
//   4. physics   integrate (guarded: a NaN or an explosion is refused,
//                counted and the state restored), contacts with floor/blade;
//   5. metrics   record the frame.
// The spring model is rebuilt only when the frontier changed, so a frame
// with a still scalpel costs the integration alone.

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "cut/made_vertex.h"
#include "cut/mt/time_critical_cutter.h"
#include "cut/stroke_sweep.h"
#include "engine/mt/frontier.h"
#include "engine/mt/mt.h"
#include "engine/mt/selective_refinement.h"
#include "engine/mt/tet_bvh.h"
#include "sim/model_build.h"
#include "sim/scalpel.h"
#include "sim/spring_model.h"
#include "sim/spring_state.h"
#include "sim/stepper.h"
#include "sim/world_def.h"

namespace mtcut::sim {

// What one stroke of the scalpel did to the MT: from the frame its blade
// engaged to the frame its last cut finished.
struct StrokeRecord {
  std::uint64_t first_frame = 0, last_frame = 0;  // frames as FrameMetrics::frame counts them
  std::size_t live_tets_before = 0, live_tets_after = 0;  // MT tets, all resolutions
  bool finished = false;  // the blade disengaged and every cut of the stroke is done
};

struct FrameMetrics {
  std::uint64_t frame = 0;
  double time = 0;                 // simulated seconds at the end of the frame
  double cut_ms = 0, lod_ms = 0, physics_ms = 0, total_ms = 0;
  std::size_t frontier_tets = 0, frontier_vertices = 0, springs = 0;
  std::size_t lod_changes = 0;     // fragments added or removed this frame
  std::size_t cuts_started = 0;    // cut polygons the blade's stroke gave this frame
  std::size_t cut_tets = 0;        // MT tets the cutter replaced this frame
  std::size_t cuts_refused = 0;    // cuts taken back this frame because they would have broken the MT
  std::size_t cut_vertices = 0;    // MT vertices the cuts so far have made and use (a retracted cut's are not)
  std::size_t provisional_tets = 0;  // live pieces of the provisional cut of the stroke's part in progress
  std::size_t cut_jobs_pending = 0;
  int springs_built = 0;           // spring models made this frame (a cut's, an LOD move's taken)
  bool frozen = false;             // the cutter held the resolution this frame
  int cg_iterations = 0;
  bool step_refused = false;
};

class World {
 public:
  // Takes the MT of the organ (built by the caller from a mesh). `blade`:
  // the scalpel's pose at time 0, when the caller knows it (a scenario's
  // path, a replay, the viewer's first pose; not a live device): the
  // frontier starts where the LOD stage would move it for that pose, so
  // the first frames simulate the tissue near the blade as finely as the
  // later ones, and the first frame does not pay the refiner's first pass
  // over the MT (setup, not a frame). Without it the frontier starts at
  // the coarsest level (the finest with LOD off).
  World(engine::Mt mt, const WorldDef& def, const std::optional<ScalpelPose>& blade = std::nullopt);
  ~World();

  // Advances one frame of def.dt with the scalpel at `pose`.
  const FrameMetrics& step(const ScalpelPose& pose);
  // Advances one frame of def.dt over the scalpel's poses since the last
  // frame, in time order: each goes through the stroke sweep in turn
  // (engaged: adds to the stroke; disengaged: ends an active stroke), so a
  // stroke that turns within the frame is cut along its turns, not its
  // chord. The last pose is the frame's: LOD focus, tool contact, physics.
  // Throws std::invalid_argument for no pose.
  const FrameMetrics& step(std::span<const ScalpelPose> poses);

  const engine::Mt& mt() const { return mt_; }
  const engine::Frontier& frontier() const { return frontier_; }
  const SpringModel& model() const { return model_; }
  const SpringState& state() const { return state_; }
  const WorldDef& def() const { return def_; }
  double time() const { return time_; }
  std::uint64_t frame() const { return frame_; }
  std::uint64_t nan_events() const { return stepper_.refused_steps(); }
  // Connected pieces of the object (1 until a cut separates it).
  std::size_t pieces() const { return pieces_; }
  const cut::TimeCriticalCutter& cutter() const { return cutter_; }
  const FrameMetrics& last_frame() const { return last_; }
  // The strokes so far, oldest first (the last one may be in progress).
  const std::vector<StrokeRecord>& strokes() const { return strokes_; }

  // Deformed position of every MT vertex (visible: simulated; hidden:
  // carried by the frontier tet holding it in rest space), (n_mt_vertices).
  std::vector<Vec3> deformed_positions() const;

  // FNV-1a over the bits of every particle position (in MT vertex order)
  // and the MT's size: equal across runs iff the runs are bit-identical.
  std::uint64_t state_hash() const;

  // MT, frontier, BVH, cutter (a held provisional cut can be taken back),
  // spring model, a finite state of its size and the frontier of a pending
  // LOD move all valid (tests call it after steps).
  engine::ValidationReport validate() const;

 private:
  // The LOD field around the scalpel's blade (base to tip).
  engine::ErrorField error_field(const ScalpelPose& pose) const;
  // Makes `model` (built on frontier_) the simulated one, the state carried from `snapshot`;
  // counts it in m.springs_built.
  void adopt_model(SpringModel model, struct DeformationSnapshot snapshot, std::span<const cut::MadeVertex> made,
                   FrameMetrics& m);
  // Starts building springs on `frontier` (in the background unless def.lod
  // says inline): updating model_, which is on the tets `model_tets`
  // (in_model tells them), unless def.lod says to build from every tet.
  // The update's inputs are gathered by the build: `frontier`, the storage
  // of `model_tets` and what `in_model` reads must outlive it.
  ModelBuild start_model_build(const engine::Frontier& frontier, std::span<const engine::TetId> model_tets,
                               std::function<bool(engine::TetId)> in_model) const;
  // Takes the pending LOD move, if any: frontier, springs, state.
  void take_lod_move(FrameMetrics& m);
  // Takes the springs of this frame's cut, if building: model and state.
  void take_cut_springs(FrameMetrics& m);
  // The MT compacted when retracted cuts left more dead tets than live ones
  // and no cut is pending (TimeCriticalCutter::reclaim), and what the World
  // holds by MT id follows (the particles' vertices, the frontier).
  void reclaim_cut_storage(FrameMetrics& m);
  // Stage 2: queue the blade's sweep over the poses, run the cutter, follow its changes.
  void run_cut_stage(std::span<const ScalpelPose> poses, FrameMetrics& m);
  Environment environment_for(const ScalpelPose& pose) const;

  WorldDef def_;
  engine::Mt mt_;
  engine::TetBvh bvh_;
  engine::Frontier frontier_;
  engine::SelectiveRefiner refiner_;
  SpringModel model_;
  SpringState state_;
  Stepper stepper_;
  // The thread that builds the springs of moves and cuts (null: inline,
  // def.lod.background_build false). Declared before the builds it runs, so
  // it outlives them and finishes what they queued before it joins.
  std::unique_ptr<WorkerThread> builder_;
  // An LOD move decided at an earlier frame: the frontier it reaches, its
  // springs, and the frame whose LOD stage takes it.
  struct LodMove {
    engine::Frontier frontier;
    ModelBuild springs;
    std::uint64_t take_at = 0;
  };
  std::optional<LodMove> lod_move_;
  // The springs of the frontier a cut left, building while the LOD stage
  // decides the next move (their inputs are copies), taken before the physics.
  struct CutSprings;
  std::unique_ptr<CutSprings> cut_springs_;
  // Where the refiner moves frontier_: a copy of it, made again only when
  // their versions differ, after a move or a cut (a frame with a still
  // blade copies nothing).
  engine::Frontier lod_target_;
  cut::StrokeSweep stroke_;  // the engaged blade's poses, merged into cut polygons
  cut::TimeCriticalCutter cutter_;
  // The blade's ends at the part's last cut (world space): a recorded part
  // grows by the sweep from there (run_cut_stage).
  std::vector<Vec3> part_cut_blade_;
  std::size_t pieces_ = 0;  // counted when the World is made, then as the cutter reports them
  std::size_t cut_vertices_ = 0;  // FrameMetrics::cut_vertices
  std::vector<StrokeRecord> strokes_;
  ScalpelPose last_pose_;
  double time_ = 0;
  std::uint64_t frame_ = 0;
  FrameMetrics last_;
};

}  // namespace mtcut::sim
