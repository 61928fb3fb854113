#include "app/view/viewer_panel.h"

#include <algorithm>
#include <imgui.h>

#include "app/view/viewer_input.h"
#include "engine/input_error.h"

namespace mtcut::app::view {
namespace {

bool input_double(const char* label, double& value, double step, const char* format) {
  return ImGui::InputDouble(label, &value, step, step * 10, format);
}

}  // namespace

PanelRequests ViewerPanel::draw(ViewerSession& session, const PanelStatus& status) {
  PanelRequests requests;
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::Begin("mtcut", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::TextUnformatted(session.scenario().file.c_str());
  draw_timings(session, status);
  draw_model(session);
  requests.clear_clock = draw_controls(session);
  if (ImGui::CollapsingHeader("World settings")) requests.clear_clock |= draw_world_settings(session);
  if (ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen)) draw_display(session);
  if (ImGui::CollapsingHeader("Record and replay", ImGuiTreeNodeFlags_DefaultOpen))
    requests.clear_clock |= draw_trace(session);
  if (session.hid() && ImGui::CollapsingHeader("HID device", ImGuiTreeNodeFlags_DefaultOpen)) draw_hid(session);
  requests.screenshot = ImGui::Button("Screenshot");
  if (ImGui::CollapsingHeader("Help")) ImGui::TextUnformatted(kInputHelp);
  ImGui::End();
  return requests;
}

void ViewerPanel::draw_timings(ViewerSession& session, const PanelStatus& status) {
  TimingHistory& t = session.timings();
  ImGui::Text("frame ms: cut %.2f  LOD %.2f  physics %.2f  render %.2f", t.cut.last(), t.lod.last(),
              t.physics.last(), status.render_ms);
  ImGui::PlotLines("physics", t.physics.data(), t.physics.capacity(), t.physics.offset(), nullptr, 0.0f,
                   std::max(t.physics.max(), 1.0f), ImVec2(0, 40));
  ImGui::PlotLines("render", t.render.data(), t.render.capacity(), t.render.offset(), nullptr, 0.0f,
                   std::max(t.render.max(), 1.0f), ImVec2(0, 40));
  ImGui::Text("display %.0f fps", status.display_fps);
  if (status.sim_speed >= 0) {
    ImGui::SameLine();
    ImGui::Text(", simulation at %.0f%% of real time", 100.0 * status.sim_speed);
  }
  if (status.dropped_steps > 0)
    ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "behind: %llu steps dropped",
                       static_cast<unsigned long long>(status.dropped_steps));
}

void ViewerPanel::draw_model(const ViewerSession& session) {
  const sim::World& w = session.world();
  ImGui::Text("frame %llu, t = %.2f s", static_cast<unsigned long long>(w.frame()), w.time());
  ImGui::Text("frontier: %zu tets, %zu vertices, %zu springs", w.frontier().tets().size(),
              w.frontier().vertices().size(), w.model().num_springs());
  ImGui::Text("pieces: %d   surface faces: %zu", session.topology().pieces, session.topology().num_faces());
  ImGui::Text("MT: %zu vertices (%zu made by cuts), %zu live tets", w.mt().num_vertices(),
              w.mt().num_vertices() - session.loaded_vertices(), w.mt().num_live_tets());
  ImGui::Text("pending cut jobs: %zu%s", w.last_frame().cut_jobs_pending, w.cutter().frozen() ? " (resolution frozen)" : "");
  if (w.nan_events() > 0) ImGui::Text("refused steps (NaN or explosion): %llu", static_cast<unsigned long long>(w.nan_events()));
}

bool ViewerPanel::draw_controls(ViewerSession& session) {
  bool clear_clock = false;
  ViewSettings& s = session.settings();
  if (ImGui::Button(s.paused ? "Run" : "Pause")) {
    s.paused = !s.paused;
    clear_clock = true;
  }
  ImGui::SameLine();
  if (ImGui::Button("Step")) {
    s.paused = true;
    session.step();
  }
  ImGui::SameLine();
  if (ImGui::Button("Reset")) {
    session.reset();
    clear_clock = true;
  }
  ImGui::SameLine();
  ImGui::Checkbox("scripted scalpel", &s.play_script);
  MouseScalpelDef& blade = session.mouse_scalpel().def();
  const double min_depth = 0.002, max_depth = 0.1;
  ImGui::SliderScalar("blade depth (m)", ImGuiDataType_Double, &blade.depth, &min_depth, &max_depth, "%.3f");
  return clear_clock;
}

bool ViewerPanel::draw_world_settings(ViewerSession& session) {
  ImGui::Checkbox("LOD around the blade", &edited_.lod.enabled);
  input_double("near radius (m)", edited_.lod.near_radius, 0.001, "%.3f");
  input_double("near error", edited_.lod.near_error, 0.0005, "%.4f");
  input_double("far radius (m)", edited_.lod.far_radius, 0.005, "%.3f");
  input_double("far error", edited_.lod.far_error, 0.01, "%.3f");
  input_double("Young's modulus (Pa)", edited_.material.youngs_modulus, 100, "%.0f");
  input_double("stiffness damping (s)", edited_.material.stiffness_damping, 0.0005, "%.4f");
  input_double("mass damping (1/s)", edited_.material.mass_damping, 0.1, "%.2f");
  int unit = edited_.cut_budget.unit == sim::CutBudgetDef::Unit::kTets ? 0 : 1;
  ImGui::Combo("budget unit", &unit, "tets\0milliseconds\0");
  edited_.cut_budget.unit = unit == 0 ? sim::CutBudgetDef::Unit::kTets : sim::CutBudgetDef::Unit::kMilliseconds;
  input_double("cut budget / frame", edited_.cut_budget.amount, unit == 0 ? 100 : 0.5, "%.1f");
  int kind = edited_.integrator.kind == sim::IntegratorKind::kImplicitEuler ? 0 : 1;
  ImGui::Combo("integrator", &kind, "implicit Euler\0symplectic Euler\0");
  edited_.integrator.kind = kind == 0 ? sim::IntegratorKind::kImplicitEuler : sim::IntegratorKind::kSymplecticEuler;
  ImGui::SliderInt("substeps", &edited_.integrator.substeps, 1, 32);
  // Values a World refuses (negative, inverted radii) are clamped here, not passed on.
  edited_.lod.near_radius = std::max(edited_.lod.near_radius, 0.0);
  edited_.lod.far_radius = std::max(edited_.lod.far_radius, edited_.lod.near_radius);
  edited_.lod.near_error = std::max(edited_.lod.near_error, 0.0);
  edited_.lod.far_error = std::max(edited_.lod.far_error, edited_.lod.near_error);
  edited_.material.youngs_modulus = std::max(edited_.material.youngs_modulus, 1.0);
  edited_.material.stiffness_damping = std::max(edited_.material.stiffness_damping, 0.0);
  edited_.material.mass_damping = std::max(edited_.material.mass_damping, 0.0);
  edited_.cut_budget.amount = std::max(edited_.cut_budget.amount, 0.0);
  if (ImGui::Button("Apply and reset")) {
    session.reset(edited_);
    return true;
  }
  ImGui::SameLine();
  if (ImGui::Button("Revert")) edited_ = session.world().def();
  return false;
}

bool ViewerPanel::draw_trace(ViewerSession& session) {
  ImGui::InputText("trace file", trace_path_.data(), trace_path_.size());
  const std::string path = trace_path_.data();
  bool restarted = false;
  try {
    if (!session.recording()) {
      if (ImGui::Button("Record from reset")) {
        session.start_recording();
        trace_message_ = "recording (the World started again)";
        restarted = true;
      }
    } else if (ImGui::Button("Stop and save")) {
      const std::size_t n = session.stop_recording(path);
      trace_message_ = "wrote " + std::to_string(n) + " poses to " + path;
    }
    ImGui::SameLine();
    if (ImGui::Button("Replay")) {
      session.replay_trace(path);
      trace_message_ = "replaying " + path;
      restarted = true;
    }
  } catch (const engine::InputError& e) {
    trace_message_ = e.what();
  }
  if (session.recording()) {
    ImGui::SameLine();
    ImGui::TextColored(ImVec4(1.0f, 0.3f, 0.3f, 1.0f), "REC");
  }
  if (!trace_message_.empty()) ImGui::TextWrapped("%s", trace_message_.c_str());
  return restarted;
}

void ViewerPanel::draw_hid(const ViewerSession& session) {
  const hid::InputStatus status = session.hid()->status();
  if (status.connected)
    ImGui::TextColored(ImVec4(0.4f, 1.0f, 0.4f, 1.0f), "connected: %s", status.device_path.c_str());
  else
    ImGui::TextColored(ImVec4(1.0f, 0.5f, 0.3f, 1.0f), "%s", status.unplugs > 0 ? "lost: reconnecting" : "looking for the device");
  const hid::LatencySummary latency = session.hid()->latency();
  ImGui::Text("samples %ld (rejected %ld), unplugs %ld", status.samples, status.counts.rejected(), status.unplugs);
  ImGui::Text("sample-to-cut latency: median %.1f ms, last %.1f ms, max %.1f ms", latency.median_ms, latency.last_ms,
              latency.max_ms);
  if (!session.hid_message().empty()) ImGui::TextWrapped("%s", session.hid_message().c_str());
}

void ViewerPanel::draw_display(ViewerSession& session) {
  ViewSettings& s = session.settings();
  int surface = s.surface == SurfaceKind::kFinest ? 0 : 1;
  bool surface_changed = ImGui::RadioButton("finest surface", &surface, 0);
  ImGui::SameLine();
  surface_changed |= ImGui::RadioButton("simulated frontier", &surface, 1);
  if (surface_changed) {
    s.surface = surface == 0 ? SurfaceKind::kFinest : SurfaceKind::kFrontier;
    session.refresh_surface();
  }
  int shading = s.shading == Shading::kSmooth ? 0 : 1;
  bool shading_changed = ImGui::RadioButton("smooth", &shading, 0);
  ImGui::SameLine();
  shading_changed |= ImGui::RadioButton("flat", &shading, 1);
  if (shading_changed) {
    s.shading = shading == 0 ? Shading::kSmooth : Shading::kFlat;
    session.refresh_surface();
  }
  int colors = s.color_mode == ColorMode::kPieces ? 0 : 1;
  ImGui::RadioButton("pieces and cuts", &colors, 0);
  ImGui::SameLine();
  ImGui::RadioButton("LOD levels", &colors, 1);
  s.color_mode = colors == 0 ? ColorMode::kPieces : ColorMode::kLodLevels;
  if (s.color_mode == ColorMode::kLodLevels)
    ImGui::Text("blue: finest (level 0) ... red: coarsest (level %d)", session.topology().max_level);
  ImGui::Checkbox("wireframe", &s.wireframe);
  ImGui::SameLine();
  ImGui::Checkbox("floor", &s.show_floor);
  ImGui::SameLine();
  ImGui::Checkbox("blade", &s.show_blade);
}

}  // namespace mtcut::app::view
