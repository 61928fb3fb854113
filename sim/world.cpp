#include "sim/world.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <iterator>
#include <optional>
#include <stdexcept>

#include "absl/container/flat_hash_map.h"
#include "cut/cut_polygon.h"
#include "cut/mt/cut_retraction.h"
#include "engine/input_error.h"
#include "sim/forces.h"
#include "sim/rest_space_cut.h"
#include "sim/state_transfer.h"

namespace mtcut::sim {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

struct World::CutSprings {
  ModelBuild springs;
  DeformationSnapshot snapshot;        // before the cut
  std::vector<cut::MadeVertex> made;   // the vertices it made, ascending ids
};

World::~World() {
  // Pending builds read members destroyed before the worker joins.
  if (lod_move_) lod_move_->springs.wait();
  if (cut_springs_) cut_springs_->springs.wait();
}

World::World(engine::Mt mt, const WorldDef& def, const std::optional<ScalpelPose>& blade)
    : def_(def), mt_(std::move(mt)), bvh_(mt_) {
  if (def_.lod.background_build) builder_ = std::make_unique<WorkerThread>();
  cutter_.reserve(mt_);  // room for the strokes' cuts, made now rather than in a frame
  frontier_ = def_.lod.enabled ? engine::Frontier::coarsest(mt_) : engine::Frontier::finest(mt_);
  if (def_.lod.enabled && blade) refiner_.update(mt_, error_field(*blade), frontier_);
  model_ = ModelInputs::of(mt_, frontier_, def_.material, def_.fixed).build();
  state_ = rest_state(model_);
  pieces_ = cut::count_pieces(mt_);  // the cutter reports them once a cut may change them
}

engine::ErrorField World::error_field(const ScalpelPose& pose) const {
  engine::ErrorField field;
  field.focus = engine::Segment{pose.base, pose.tip};
  field.radius = def_.lod.near_radius;
  field.near_error = def_.lod.near_error;
  const double span = std::max(1e-9, def_.lod.far_radius - def_.lod.near_radius);
  field.growth = std::max(0.0, def_.lod.far_error - def_.lod.near_error) / span;
  return field;
}

Environment World::environment_for(const ScalpelPose& pose) const {
  Environment env = def_.environment;
  if (!pose.engaged && def_.tool_radius > 0) env.tool = Capsule{pose.base, pose.tip, def_.tool_radius};
  return env;
}

// The implicit warm start is carried over as the velocities are, not
// restarted from 0: a frontier that follows the scalpel changes every few
// frames (the liver scenario: 73 times in 150 frames, each such frame's CG
// iterations 3.0 -> 1.6 on average). The stepper's history is always that
// of the current model (it is resized at each step and carried at each
// rebuild); the explicit integrator has none worth carrying.
void World::adopt_model(SpringModel model, DeformationSnapshot snapshot, std::span<const cut::MadeVertex> made,
                        FrameMetrics& m) {
  model_ = std::move(model);
  ++m.springs_built;
  if (def_.integrator.kind == IntegratorKind::kImplicitEuler) snapshot.carried = stepper_.take_warm_start_history();
  std::vector<std::vector<Vec3>> carried;
  state_ = transfer_state(mt_, bvh_, snapshot, model_, made, nullptr,
                          &carried, frontier_.tets());
  stepper_.carry_warm_start(std::move(carried));
}

ModelBuild World::start_model_build(const engine::Frontier& frontier, std::span<const engine::TetId> model_tets,
                                    std::function<bool(engine::TetId)> in_model) const {
  if (!def_.lod.update_springs)
    return ModelBuild(ModelInputs::of(mt_, frontier, def_.material, def_.fixed), builder_.get());
  // The change is gathered where the build runs, off the frame's thread.
  // What it reads stays as it is until the build is taken: model_ (every
  // adoption takes the pending build first), the MT and frontier_ (a cut
  // stage takes a pending move before it cuts; a cut's springs are taken in
  // the frame's LOD stage, before the next cut stage), and what the caller
  // keeps for it (the move's frontier, the cut's snapshot).
  return ModelBuild(
      [this, &frontier, model_tets, in_model = std::move(in_model)] {
        return ModelInputs::change_from(model_, model_tets, in_model, mt_, frontier, def_.material, def_.fixed);
      },
      builder_.get());
}

void World::take_lod_move(FrameMetrics& m) {
  if (!lod_move_) return;
  DeformationSnapshot snapshot = take_snapshot(mt_, frontier_, model_, state_);
  SpringModel model = lod_move_->springs.take();
  std::swap(frontier_, lod_move_->frontier);
  lod_target_ = std::move(lod_move_->frontier);  // the old frontier's storage, for the next copy
  lod_move_.reset();
  adopt_model(std::move(model), std::move(snapshot), {}, m);
}

void World::take_cut_springs(FrameMetrics& m) {
  if (!cut_springs_) return;
  const std::unique_ptr<CutSprings> cut = std::move(cut_springs_);
  // Taken before the snapshot moves: the build reads it until it ends.
  SpringModel model = cut->springs.take();
  adopt_model(std::move(model), std::move(cut->snapshot), cut->made, m);
}

void World::reclaim_cut_storage(FrameMetrics& m) {
  // At the start of the cut stage: a cut's springs were taken in the frame
  // of the cut; a pending LOD move holds a frontier and a build over the
  // MT's ids, so it is taken first, as before a cut.
  if (cut_springs_ || !cutter_.reclaimable(mt_)) return;
  take_lod_move(m);
  const std::optional<engine::Mt::Compaction> compaction = cutter_.reclaim(mt_, bvh_);
  if (!compaction) return;
  // Ids keep their order (Mt::compact), so the particles keep theirs (it
  // breaks ties by vertex id): the model and state stay as they are.
  for (VertId& v : model_.particle_vertex) v = compaction->vertex(v);
  frontier_ = engine::Frontier::from_fragments(mt_, frontier_.fragments());
  lod_target_ = frontier_;
}

void World::run_cut_stage(std::span<const ScalpelPose> poses, FrameMetrics& m) {
  // The stroke's polygons: every pose of the frame goes through the sweep in
  // order, so a turn within the frame ends a part there. A part that ended
  // is cut for good; the part in progress is cut provisionally, every frame
  // its blade moves (cut_retraction.h says how and why).
  reclaim_cut_storage(m);
  std::vector<cut::BladePose> blades;
  blades.reserve(poses.size());
  for (const ScalpelPose& pose : poses) blades.push_back({pose.base, pose.tip, pose.engaged});
  const bool was_active = stroke_.active();
  cut::StrokeAdvance advance = stroke_.advance(blades);
  if (!was_active && (stroke_.active() || !advance.ended.empty()))
    strokes_.push_back({frame_, frame_, mt_.num_live_tets(), mt_.num_live_tets(), false});
  // A blade moving outside the tissue (its sweep's box clear of the
  // particles') leaves the part's cut as it is.
  const auto sweeps_tissue = [&] {
    engine::Aabb tissue;
    for (const Vec3& x : state_.x) tissue.extend(x);
    return advance.swept.overlaps(tissue);
  };
  const bool recut = !advance.ended.empty() || (cutter_.provisional_held() && !stroke_.active()) ||
                     (advance.moved && sweeps_tissue());
  if (!recut && !cutter_.frozen()) return;
  take_lod_move(m);  // the MT is about to change
  DeformationSnapshot snapshot = take_snapshot(mt_, frontier_, model_, state_);
  // The vertices a retraction left unused, by key: the same point made
  // again takes their state (an incision that has opened stays open).
  absl::flat_hash_map<cut::PointKey, VertId, cut::PointKeyHash> provisional_points;
  if (recut) {
    // Cut in rest space (rest_space_cut.h says why).
    std::vector<Vec3> rest(model_.num_particles());
    for (std::size_t p = 0; p < rest.size(); ++p) rest[p] = mt_.position(model_.particle_vertex[p]);
    for (auto& polygon : advance.ended) polygon = rest_space_polygon(polygon, rest, state_.x);
    std::optional<cut::CutPolygon> current = stroke_.current();
    if (current) {
      // A part the cutter records (its plane fixed in rest space) grows by
      // what the blade swept since the part's last cut, carried to rest
      // space by the map that fits the tissue where the blade is now (the
      // cutter joins it to the part's polygon: TimeCriticalCutter::recut);
      // a part's first cut is its whole polygon.
      std::optional<cut::CutPolygon> swept;
      if (cutter_.part_record() && advance.ended.empty() && !part_cut_blade_.empty()) {
        std::vector<Vec3> ends = part_cut_blade_;
        for (const cut::BladePose& b : blades)
          if (b.engaged) ends.insert(ends.end(), {b.base, b.tip});
        try {
          swept = cut::CutPolygon::on_plane_of(*current, ends, "scalpel sweep");
        } catch (const engine::InputError&) {
          // the blade swept no area on the part's plane: its whole polygon
        }
      }
      current = rest_space_polygon(swept ? *swept : *current, rest, state_.x);
    }
    part_cut_blade_.clear();
    if (stroke_.active() && !blades.empty() && blades.back().engaged)
      part_cut_blade_ = {blades.back().base, blades.back().tip};
    m.cuts_started = advance.ended.size() + (current ? 1 : 0);
    if (const auto retraction =
            cutter_.recut(mt_, bvh_, advance.ended, advance.turned_back, current, stroke_.plane_fixed())) {
      cut::follow_retraction(mt_, frontier_, *retraction);
      for (const cut::MadeVertex& made : retraction->unused) provisional_points.emplace(made.key, made.id);
      cut_vertices_ -= retraction->unused.size();
      if (m.cuts_started == 0 && retraction->fragments_removed > 0)
        pieces_ = cut::count_pieces(mt_);  // the stroke left nothing to cut
    }
  }
  const cut::CutBudget budget = def_.cut_budget.unit == CutBudgetDef::Unit::kTets
                                    ? cut::CutBudget::units(static_cast<std::size_t>(def_.cut_budget.amount))
                                    : cut::CutBudget::ms(def_.cut_budget.amount);
  auto result = cutter_.run(mt_, bvh_, frontier_, budget);
  cut::follow_cut(mt_, frontier_, result.changes);
  cut_vertices_ += result.changes.made_vertices.size();
  while (result.refused) {  // the cut would have broken the MT (cut_guard.h): taken back
    cut::follow_retraction(mt_, frontier_, *result.refused);
    cut_vertices_ -= result.refused_reported_vertices;
    ++m.cuts_refused;
    result.refused.reset();
    // A refusal ends the cutter's call: what it queued behind (a part's
    // last front again, TimeCriticalCutter) runs now.
    if (!cutter_.frozen()) break;
    auto more = cutter_.run(mt_, bvh_, frontier_, budget);
    cut::follow_cut(mt_, frontier_, more.changes);
    cut_vertices_ += more.changes.made_vertices.size();
    result.changes.append(more.changes);
    result.cuts_finished += more.cuts_finished;
    if (more.pieces) result.pieces = std::move(more.pieces);
    result.refused = std::move(more.refused);
    result.refused_reported_vertices = more.refused_reported_vertices;
  }
  if (!strokes_.empty() && !strokes_.back().finished) {
    StrokeRecord& stroke = strokes_.back();
    stroke.last_frame = frame_;
    stroke.live_tets_after = mt_.num_live_tets();
    stroke.finished = !stroke_.active() && !cutter_.frozen();
  }
  m.cut_tets = result.changes.replaced.size();
  if (result.pieces) pieces_ = *result.pieces;
  // Jobs of hidden fragments (a small budget defers them to later frames)
  // change tets no frontier tet is: the springs stay as they are, where a
  // rebuild would cost each such frame a model (liver, budget_tets = 5:
  // ~5 ms a frame for ten frames).
  const auto tets = frontier_.tets();
  const auto was_simulated = [&](engine::TetId t) { return snapshot.simulated(t); };
  const bool mesh_changed =
      tets.size() != snapshot.simulated_tets.size() || !std::all_of(tets.begin(), tets.end(), was_simulated);
  if (mesh_changed) {
    // A point made again where a retraction left a simulated one takes that
    // one's state: its only parent.
    std::vector<cut::MadeVertex> made = std::move(result.changes.made_vertices);
    for (cut::MadeVertex& v : made) {
      const auto again = provisional_points.find(v.key);
      if (again != provisional_points.end() && snapshot.particle_of[again->second.index()] >= 0) {
        v.parents = {again->second, VertId(), VertId(), VertId()};
        v.weights = {1.0, 0.0, 0.0, 0.0};
      }
    }
    cut_springs_ = std::make_unique<CutSprings>(CutSprings{ModelBuild(), std::move(snapshot), std::move(made)});
    const DeformationSnapshot& before = cut_springs_->snapshot;
    cut_springs_->springs = start_model_build(frontier_, before.simulated_tets.members(),
                                              [&before](engine::TetId t) { return before.simulated(t); });
  }
}

const FrameMetrics& World::step(const ScalpelPose& pose) { return step(std::span<const ScalpelPose>(&pose, 1)); }

const FrameMetrics& World::step(std::span<const ScalpelPose> poses) {
  if (poses.empty()) throw std::invalid_argument("World::step: a frame needs at least one scalpel pose");
  const auto frame_start = Clock::now();
  FrameMetrics m;
  m.frame = frame_;
  // Stage 1, scalpel: the last pose is the frame's.
  const ScalpelPose& pose = poses.back();

  // Stage 2, cut.
  const auto cut_start = Clock::now();
  run_cut_stage(poses, m);
  m.cut_ms = ms_since(cut_start);
  m.frozen = cutter_.frozen();
  m.cut_jobs_pending = cutter_.progress().jobs_pending;

  // Stage 3, lod. A cut's springs are taken (and timed as the cut's) once
  // the refiner has run beside their build, before a move's build starts.
  const auto lod_start = Clock::now();
  double cut_springs_ms = 0;
  const auto take_cut = [&] {
    const auto start = Clock::now();
    take_cut_springs(m);
    cut_springs_ms += ms_since(start);
  };
  if (def_.lod.enabled && !cutter_.frozen()) {
    if (lod_move_ && frame_ >= lod_move_->take_at) take_lod_move(m);  // none after a cut: the cut stage took it
    if (!lod_move_) {
      // A frontier's version names its state (a copy shares it while
      // identical): a still blade and no cut leave the copy as it is.
      if (lod_target_.version() != frontier_.version()) lod_target_ = frontier_;
      const auto stats = refiner_.update(mt_, error_field(pose), lod_target_);
      m.lod_changes = stats.refined + stats.coarsened;
      take_cut();
      if (lod_target_.version() != frontier_.version()) {
        const auto take_at = frame_ + static_cast<std::uint64_t>(std::max(1, def_.lod.build_frames));
        lod_move_.emplace(LodMove{std::move(lod_target_), ModelBuild(), take_at});
        lod_move_->springs = start_model_build(lod_move_->frontier, frontier_.tets(),
                                               [this](engine::TetId t) { return frontier_.has_tet(t); });
      }
    }
  }
  take_cut();
  m.lod_ms = ms_since(lod_start) - cut_springs_ms;
  m.cut_ms += cut_springs_ms;

  // Stage 4, physics.
  const auto physics_start = Clock::now();
  const StepReport report = stepper_.step(model_, environment_for(pose), def_.integrator, state_, def_.dt);
  m.physics_ms = ms_since(physics_start);
  m.cg_iterations = report.cg_iterations;
  m.step_refused = !report.accepted;

  // Stage 5, metrics.
  last_pose_ = pose;
  time_ += def_.dt;
  ++frame_;
  m.time = time_;
  m.frontier_tets = frontier_.tets().size();
  m.frontier_vertices = frontier_.vertices().size();
  m.springs = model_.num_springs();
  m.cut_vertices = cut_vertices_;
  m.provisional_tets = cutter_.provisional_changes() ? cutter_.provisional_changes()->made_tets.size() : 0;
  m.total_ms = ms_since(frame_start);
  last_ = m;
  return last_;
}

std::vector<Vec3> World::deformed_positions() const {
  const DeformationSnapshot snapshot = take_snapshot(mt_, frontier_, model_, state_);
  std::vector<Vec3> out(mt_.num_vertices());
  for (std::size_t v = 0; v < out.size(); ++v) out[v] = sample_vertex(mt_, bvh_, snapshot, VertId(v)).first;
  return out;
}

std::uint64_t World::state_hash() const {
  std::vector<std::pair<std::int32_t, std::size_t>> order;  // (MT vertex, particle)
  order.reserve(model_.num_particles());
  for (std::size_t p = 0; p < model_.num_particles(); ++p) order.emplace_back(model_.particle_vertex[p].value, p);
  std::sort(order.begin(), order.end());
  std::uint64_t hash = 1469598103934665603ULL;
  auto mix = [&](const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 1099511628211ULL;
  };
  const std::uint64_t sizes[2] = {mt_.num_vertices(), mt_.num_live_tets()};
  mix(sizes, sizeof sizes);
  for (const auto& [vertex, p] : order) {
    mix(&vertex, sizeof vertex);
    mix(state_.x[p].data(), 3 * sizeof(double));
  }
  return hash;
}

engine::ValidationReport World::validate() const {
  engine::ValidationReport report = mt_.validate();
  for (auto& p : engine::validate_frontier(mt_, frontier_).problems) report.add("frontier: " + p);
  for (auto& p : model_.validate().problems) report.add("springs: " + p);
  if (state_.x.size() != model_.num_particles() || state_.v.size() != state_.x.size())
    report.add("state and spring model differ in size");
  const auto finite = [](const std::vector<Vec3>& values) {
    return std::all_of(values.begin(), values.end(), [](const Vec3& p) { return p.allFinite(); });
  };
  if (!finite(state_.x)) report.add("state: a position is not finite");
  if (!finite(state_.v)) report.add("state: a velocity is not finite");
  for (auto& p : bvh_.validate(mt_).problems) report.add("bvh: " + p);
  for (auto& p : cutter_.validate(mt_).problems) report.add(p);
  // A move decided at an earlier frame reaches a frontier of the MT as it is
  // now (a cut takes any pending move first).
  if (lod_move_)
    for (auto& p : engine::validate_frontier(mt_, lod_move_->frontier).problems) report.add("pending LOD move: " + p);
  return report;
}

}  // namespace mtcut::sim
