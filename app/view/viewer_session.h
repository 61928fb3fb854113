#pragma once
// Everything the viewer shows and steers, without a window: the scenario,
// the World built from it, the surface drawn of it, the mouse scalpel and
// the display settings. The window (viewer_window.h), the headless
// screenshot run and the tests all drive this one object, so the mouse path
// a test exercises is the one a user's mouse takes.

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/hid/hid_feed.h"
#include "app/scenario.h"
#include "app/view/frame_history.h"
#include "app/view/mouse_scalpel.h"
#include "app/view/surface_colors.h"
#include "app/view/surface_geometry.h"
#include "app/view/surface_topology.h"
#include "sim/world.h"

namespace mtcut::app::view {

struct ViewSettings {
  SurfaceKind surface = SurfaceKind::kFinest;  // the scenario's [output] surface at the start
  Shading shading = Shading::kSmooth;
  ColorMode color_mode = ColorMode::kPieces;
  bool wireframe = false;
  bool show_floor = true;
  bool show_blade = true;
  bool play_script = true;  // the scenario's scalpel path drives the blade when the mouse does not
  bool paused = false;
};

// Per-frame timings for the panel's plots, ms.
struct TimingHistory {
  FrameHistory cut, lod, physics, render;
};

class ViewerSession {
 public:
  // Builds the scenario's organ and its MT (throws InputError on a bad mesh).
  explicit ViewerSession(ScenarioDef scenario);

  // Runs one frame of physics with next_poses(), then refreshes the surface.
  const sim::FrameMetrics& step();
  // The poses the next step uses, in time order: a mouse stroke first, then
  // a trace being replayed (its samples since the last step and its pose
  // now), then the HID device when attached (its samples since the last
  // step and its path's pose now), then the scenario's path (when
  // settings.play_script), else the blade parked above the organ. One pose
  // except from a trace or the device.
  std::vector<sim::ScalpelPose> next_poses();

  // The HID device drives the blade (`mtcut view --hid`); null detaches.
  // `feed` is live, outlives the session or is detached first.
  void attach_hid(hid::HidFeed* feed) { hid_ = feed; }
  const hid::HidFeed* hid() const { return hid_; }
  // Takes the device's events (each once), prints them to stderr and keeps
  // the last one for the panel. Call every displayed frame.
  void poll_hid();
  const std::string& hid_message() const { return hid_message_; }

  // Recording what the user does (mouse, device, script) as a scalpel trace:
  // the World starts again at time 0 and every step's poses are kept (a
  // step's last at its World time, the others of the device spread evenly
  // over the step before it, so a replay gives the World the same poses).
  void start_recording();
  bool recording() const { return recording_; }
  // Writes the poses kept since start_recording() to `path` (the trace
  // format of sim/scalpel_trace.h, which `mtcut run` replays too); returns
  // how many. Throws InputError when the file cannot be written.
  std::size_t stop_recording(const std::string& path);
  // Replays a trace: the World starts again at time 0 with the trace as the
  // scalpel's path. Throws InputError "file:line: what" for a bad trace.
  void replay_trace(const std::string& path);
  bool replaying() const { return replaying_; }
  // Rebuilds the World from the MT as loaded with `def` (panel edits of
  // LOD, material, cutter budget, integrator) and starts again at time 0.
  void reset(const sim::WorldDef& def);
  void reset() { reset(world_->def()); }

  const ScenarioDef& scenario() const { return scenario_; }
  const sim::World& world() const { return *world_; }
  MouseScalpel& mouse_scalpel() { return mouse_; }
  ViewSettings& settings() { return settings_; }
  const ViewSettings& settings() const { return settings_; }
  TimingHistory& timings() { return timings_; }

  const SurfaceTopology& topology() const { return topology_; }
  const SurfaceGeometry& geometry() const { return geometry_; }
  // Bumped whenever the topology is extracted again (the renderer then
  // uploads colours and sizes again).
  std::uint64_t topology_version() const { return topology_version_; }
  // Re-extracts the topology if the frontier, the MT or settings().surface
  // changed, and the geometry always (call after changing settings().shading
  // or settings().surface).
  void refresh_surface();

  // The last pose given to the World (parked before any).
  const sim::ScalpelPose& last_pose() const { return last_pose_; }
  // Poses that were engaged and apart from the one before, also engaged:
  // sweeps the World was asked to cut.
  std::uint64_t engaged_sweeps() const { return engaged_sweeps_; }
  // MT vertices when loaded; more now means a cut made vertices.
  std::size_t loaded_vertices() const { return loaded_vertices_; }
  // The rest-space bounding box of the organ.
  const glm::dvec3& lo() const { return lo_; }
  const glm::dvec3& hi() const { return hi_; }
  sim::ScalpelPose parked_pose() const;
  // The blade's pose at time 0 as next_poses() gives it before the mouse
  // drives it (nullopt with a device: not read yet): the World starts on
  // the frontier around it.
  std::optional<sim::ScalpelPose> start_pose() const;

 private:
  // Makes the World from the MT as loaded with `def`, time 0, a replay of
  // replay_ or not.
  void start_world(const sim::WorldDef& def, bool replaying);
  ScenarioDef scenario_;
  engine::Mt loaded_mt_;
  std::size_t loaded_vertices_ = 0;
  std::unique_ptr<sim::World> world_;
  glm::dvec3 lo_{0.0}, hi_{0.0};

  MouseScalpel mouse_;
  ViewSettings settings_;
  TimingHistory timings_;

  SurfaceTopology topology_;
  SurfaceGeometry geometry_;
  std::vector<std::int32_t> levels_;  // (n_fragments) fragment_levels at levels_revision_
  std::uint64_t topology_version_ = 0;
  // What the topology was extracted from: re-extract when any differs.
  struct TopologyKey {
    std::uint64_t frontier_version = 0, mt_revision = 0;
    std::size_t particles = 0, tets = 0;
    SurfaceKind surface = SurfaceKind::kFinest;
    bool operator==(const TopologyKey&) const = default;
  } key_;
  bool topology_stale_ = true;
  std::uint64_t levels_revision_ = UINT64_MAX;

  // Keeps a step's poses at World time t in the recording.
  void record(double t, const std::vector<sim::ScalpelPose>& poses);

  sim::ScalpelPose last_pose_;
  std::uint64_t engaged_sweeps_ = 0;
  double last_step_time_ = -std::numeric_limits<double>::infinity();  // World time of the last step

  hid::HidFeed* hid_ = nullptr;  // not owned
  double hid_time_ = -1;         // the device-clock time of the last pose taken from it (-1: none)
  std::string hid_message_;

  bool recording_ = false;
  std::vector<sim::ScalpelKeyframe> recorded_;  // (steps since start_recording) World time, pose
  bool replaying_ = false;
  sim::ScalpelPath replay_;
};

}  // namespace mtcut::app::view
