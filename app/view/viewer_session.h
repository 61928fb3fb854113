#pragma once
// Everything the viewer shows and steers, without a window: the scenario,
// the World built from it, the surface drawn of it, the mouse scalpel and
// the display settings. The window (viewer_window.h), the headless
// screenshot run and the tests all drive this one object, so the mouse path
// a test exercises is the one a user's mouse takes.

#include <cstdint>
#include <memory>

#include <glm/glm.hpp>

#include "app/scenario.h"
#include "app/view/frame_history.h"
#include "app/view/mouse_scalpel.h"
#include "app/view/surface_colors.h"
#include "app/view/surface_geometry.h"
#include "app/view/surface_topology.h"
#include "sim/world.h"

namespace mtcut::app::view {

struct ViewSettings {
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

  // Runs one frame of physics with next_pose(), then refreshes the surface.
  const sim::FrameMetrics& step();
  // The pose the next step uses: a mouse stroke first, else the scenario's
  // path (when settings.play_script), else the blade parked above the organ.
  sim::ScalpelPose next_pose();
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
  // Re-extracts the topology if the frontier or the MT changed, and the
  // geometry always (call after changing settings().shading).
  void refresh_surface();

  // The pose given to the World in the last step (parked before any).
  const sim::ScalpelPose& last_pose() const { return last_pose_; }
  // Steps whose pose and the one before were both engaged and apart: sweeps
  // the World was asked to cut.
  std::uint64_t engaged_sweeps() const { return engaged_sweeps_; }
  // MT vertices when loaded; more now means a cut made vertices.
  std::size_t loaded_vertices() const { return loaded_vertices_; }
  // The rest-space bounding box of the organ.
  const glm::dvec3& lo() const { return lo_; }
  const glm::dvec3& hi() const { return hi_; }
  sim::ScalpelPose parked_pose() const;

 private:
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
    bool operator==(const TopologyKey&) const = default;
  } key_;
  bool topology_stale_ = true;
  std::uint64_t levels_revision_ = UINT64_MAX;

  sim::ScalpelPose last_pose_;
  std::uint64_t engaged_sweeps_ = 0;
};

}  // namespace mtcut::app::view
