#pragma once
// The Dear ImGui panel: frame-time breakdown with live plots, model figures,
// simulation controls (pause, step, reset, scripted path), recording what
// the user does to a scalpel trace and replaying one, the HID device's
// status (connected or lost, sample-to-cut latency), the World's settings
// (LOD, material, cutter budget, integrator: edited, then applied by
// resetting the World with them), display options and a screenshot button.
// Needs an ImGui frame in progress.

#include <array>
#include <cstdint>
#include <string>

#include "app/view/viewer_session.h"
#include "sim/world_def.h"

namespace mtcut::app::view {

// What the window measures and the session does not know.
struct PanelStatus {
  double render_ms = 0;             // drawing the last displayed frame
  double display_fps = 0;
  std::uint64_t dropped_steps = 0;  // physics steps dropped to keep the UI live
  double sim_speed = -1;            // simulated / wall-clock time over the last second (-1: not measured)
};

// Actions the window carries out after the frame.
struct PanelRequests {
  bool screenshot = false;
  bool clear_clock = false;  // the World was reset or unpaused: forget accumulated time
};

class ViewerPanel {
 public:
  explicit ViewerPanel(const sim::WorldDef& def) : edited_(def) {}
  PanelRequests draw(ViewerSession& session, const PanelStatus& status);

 private:
  void draw_timings(ViewerSession& session, const PanelStatus& status);
  void draw_model(const ViewerSession& session);
  bool draw_controls(ViewerSession& session);
  bool draw_world_settings(ViewerSession& session);
  void draw_display(ViewerSession& session);
  bool draw_trace(ViewerSession& session);
  void draw_hid(const ViewerSession& session);

  sim::WorldDef edited_;  // the World's settings as edited, applied by "Apply and reset"
  std::array<char, 512> trace_path_{"mtcut-trace.csv"};  // the trace file to record to or replay
  std::string trace_message_;                           // what the last record or replay did
};

}  // namespace mtcut::app::view
