#include "app/view/viewer_session.h"

#include <iostream>
#include <limits>

#include "app/fragment_levels.h"
#include "app/run_command.h"
#include "sim/scalpel_trace.h"

namespace mtcut::app::view {
namespace {

bool apart(const sim::ScalpelPose& a, const sim::ScalpelPose& b) {
  return (a.base - b.base).norm() > 1e-9 || (a.tip - b.tip).norm() > 1e-9;
}

}  // namespace

ViewerSession::ViewerSession(ScenarioDef scenario)
    : scenario_(std::move(scenario)), loaded_mt_(build_organ_mt(scenario_)) {
  loaded_vertices_ = loaded_mt_.num_vertices();
  settings_.surface = scenario_.surface;
  lo_ = glm::dvec3(std::numeric_limits<double>::max());
  hi_ = glm::dvec3(std::numeric_limits<double>::lowest());
  for (const engine::Vec3& p : loaded_mt_.positions()) {
    lo_ = glm::min(lo_, glm::dvec3(p.x(), p.y(), p.z()));
    hi_ = glm::max(hi_, glm::dvec3(p.x(), p.y(), p.z()));
  }
  reset(scenario_.world);
}

void ViewerSession::reset(const sim::WorldDef& def) { start_world(def, false); }

void ViewerSession::start_world(const sim::WorldDef& def, bool replaying) {
  replaying_ = replaying;  // start_pose() reads it; a reset ends a replay...
  world_ = start_organ_world(scenario_, loaded_mt_, def, start_pose());
  mouse_.release();
  last_pose_ = parked_pose();
  engaged_sweeps_ = 0;
  last_step_time_ = -std::numeric_limits<double>::infinity();
  recorded_.clear();  // ...and starts a recording again from time 0
  topology_stale_ = true;
  levels_revision_ = UINT64_MAX;
  refresh_surface();
}

sim::ScalpelPose ViewerSession::parked_pose() const {
  const glm::dvec3 centre = 0.5 * (lo_ + hi_);
  const double height = hi_.z - lo_.z;
  sim::ScalpelPose pose;
  pose.base = engine::Vec3(centre.x, centre.y, hi_.z + 1.5 * height);
  pose.tip = engine::Vec3(centre.x, centre.y, hi_.z + 0.75 * height);
  pose.engaged = false;
  return pose;
}

std::optional<sim::ScalpelPose> ViewerSession::start_pose() const {
  if (replaying_) return replay_.pose_at(0.0);
  if (hid_) return std::nullopt;
  if (settings_.play_script && !scenario_.scalpel.empty()) return scenario_.scalpel.pose_at(0.0);
  return parked_pose();
}

std::vector<sim::ScalpelPose> ViewerSession::next_poses() {
  hid_time_ = -1;
  std::vector<sim::ScalpelKeyframe> device;
  if (hid_) {
    // The device's path one step behind its clock: the samples around that
    // time are in (hid_feed.h), and the window never waits for the device.
    // Taken every step, so a mouse stroke or a replay drops the device's
    // samples of its steps instead of leaving them for later.
    hid_time_ = std::max(hid_->clock() - world_->def().dt, 0.0);
    device = hid_->frame_samples(hid_time_);
  }
  if (mouse_.active()) return {mouse_.take_pose()};
  if (replaying_) return sim::poses_of(replay_.samples_between(last_step_time_, world_->time()));
  if (hid_) return sim::poses_of(device);
  if (settings_.play_script && !scenario_.scalpel.empty()) return {scenario_.scalpel.pose_at(world_->time())};
  return {parked_pose()};
}

void ViewerSession::record(double t, const std::vector<sim::ScalpelPose>& poses) {
  const double from = recorded_.empty() ? t - world_->def().dt : recorded_.back().time;
  const std::size_t n = poses.size();
  for (std::size_t k = 0; k < n; ++k) {
    const double time = k + 1 == n ? t : from + (t - from) * static_cast<double>(k + 1) / static_cast<double>(n);
    recorded_.push_back({time, poses[k]});
  }
}

const sim::FrameMetrics& ViewerSession::step() {
  const double t = world_->time();
  const std::vector<sim::ScalpelPose> poses = next_poses();
  for (const sim::ScalpelPose& pose : poses) {
    if (pose.engaged && last_pose_.engaged && apart(pose, last_pose_)) ++engaged_sweeps_;
    last_pose_ = pose;
  }
  if (recording_) record(t, poses);
  const sim::FrameMetrics& m = world_->step(poses);
  last_step_time_ = t;
  if (hid_ && hid_time_ >= 0) hid_->reached(hid_time_, hid_->clock());
  timings_.cut.push(m.cut_ms);
  timings_.lod.push(m.lod_ms);
  timings_.physics.push(m.physics_ms);
  refresh_surface();
  return m;
}

void ViewerSession::poll_hid() {
  if (!hid_) return;
  for (const hid::InputEvent& e : hid_->take_events()) {
    std::cerr << "mtcut: hid: " << e.message << "\n";
    hid_message_ = e.message;
  }
}

void ViewerSession::start_recording() {
  replaying_ = false;
  reset();
  recorded_.clear();
  recording_ = true;
}

std::size_t ViewerSession::stop_recording(const std::string& path) {
  recording_ = false;
  sim::write_scalpel_trace(path, recorded_);
  return recorded_.size();
}

void ViewerSession::replay_trace(const std::string& path) {
  replay_ = sim::read_scalpel_trace(path);
  recording_ = false;
  start_world(world_->def(), true);
}

void ViewerSession::refresh_surface() {
  const sim::World& w = *world_;
  const TopologyKey key{w.frontier().version(), w.mt().revision(), w.model().num_particles(),
                        w.frontier().tets().size(), settings_.surface};
  if (topology_stale_ || !(key == key_)) {
    if (levels_revision_ != w.mt().revision()) {
      levels_ = fragment_levels(w.mt());
      levels_revision_ = w.mt().revision();
    }
    const PieceLabels pieces = label_frontier_pieces(w.mt(), w.frontier());
    if (settings_.surface == SurfaceKind::kFinest) {
      // The carriers that still hold are kept (a frontier move walks a few
      // hundred vertices, not the whole surface).
      SurfaceTopology next = extract_finest_surface(w.mt(), w.frontier(), w.model(), pieces, levels_,
                                                    loaded_vertices_, topology_.finest ? &*topology_.finest : nullptr);
      topology_ = std::move(next);
    } else {
      topology_ = extract_surface(w.mt(), w.frontier(), w.model(), pieces, levels_, loaded_vertices_);
    }
    key_ = key;
    topology_stale_ = false;
    ++topology_version_;
  }
  update_surface_geometry(topology_, w.state().x, settings_.shading, geometry_);
}

}  // namespace mtcut::app::view
