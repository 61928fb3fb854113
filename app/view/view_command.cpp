#include "app/view/view_command.h"

#include <iomanip>
#include <iostream>
#include <memory>
#include <numeric>

#include "app/cli_checks.h"
#include "app/hid/device_choice.h"
#include "app/hid/hid_feed.h"
#include "app/hid/hidapi_transport.h"
#include "app/material_file.h"
#include "app/scenario.h"
#include "app/view/viewer_session.h"
#include "app/view/viewer_window.h"
#include "engine/input_error.h"

namespace mtcut::app {
namespace {

struct ViewOptions {
  std::string scenario;  // "" = config/scenarios/default.toml
  int frames = 0;
  std::string screenshot;
  int width = 1280, height = 720;
  bool hide_panel = false;
  bool lod_colors = false;
  bool wireframe = false;
  bool hid = false;         // --hid given
  std::string hid_profile;  // its PROFILE ("" = the one that fits a connected device)
  std::string record_hid;   // --record-hid FILE
};

double mean(const std::vector<double>& values) {
  return values.empty() ? 0.0 : std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

// Plays `frames` frames with the scripted scalpel, drawing each one as the
// interactive loop would, and reports the mean time of each stage.
void play_frames(view::ViewerSession& session, view::ViewerWindow& window, int frames) {
  std::vector<double> cut, lod, physics, render;
  for (int f = 0; f < frames; ++f) {
    session.poll_hid();
    const sim::FrameMetrics& m = session.step();
    cut.push_back(m.cut_ms);
    lod.push_back(m.lod_ms);
    physics.push_back(m.physics_ms);
    render.push_back(window.draw_frame());
  }
  if (frames > 0)
    std::cerr << std::fixed << std::setprecision(2) << "mtcut view: " << frames << " frames, mean ms: cut "
              << mean(cut) << ", LOD " << mean(lod) << ", physics " << mean(physics) << ", render " << mean(render)
              << "; " << session.world().frontier().tets().size() << " frontier tets, "
              << session.world().mt().num_vertices() - session.loaded_vertices() << " MT vertices made by cuts, "
              << session.topology().pieces << " piece(s)\n";
}

void run_view(const ViewOptions& options) {
  const std::string path =
      options.scenario.empty() ? config_dir() + "/scenarios/default.toml" : options.scenario;
  ScenarioDef scenario = load_scenario(path);
  view::require_display();
  view::ViewerSession session(std::move(scenario));
  if (options.lod_colors) session.settings().color_mode = view::ColorMode::kLodLevels;
  session.settings().wireframe = options.wireframe;
  // The device, when asked for: its thread's clock starts with the window.
  std::unique_ptr<hid::HidapiTransport> transport;
  std::unique_ptr<hid::InputThread> input;
  std::unique_ptr<hid::HidFeed> feed;
  if (options.hid) {
    transport = std::make_unique<hid::HidapiTransport>();
    hid::DeviceChoice choice = hid::choose_device(*transport, options.hid_profile, "", /*wait_for_device=*/true);
    hid::InputDef def;
    def.record_path = options.record_hid;
    input = std::make_unique<hid::InputThread>(*transport, std::move(choice.profile), def);
  } else if (!options.record_hid.empty()) {
    throw engine::InputError("--record-hid " + options.record_hid + ": records the device of a --hid session; add --hid");
  }
  view::ViewerWindow window(session, {options.width, options.height, !options.hide_panel});
  if (input) {
    input->start();
    feed = std::make_unique<hid::HidFeed>(*input, 0.0);
    session.attach_hid(feed.get());
  }
  play_frames(session, window, options.frames);
  if (!options.screenshot.empty()) {
    view::Image image;
    window.draw_frame(&image);
    view::write_png(options.screenshot, image);
    std::cerr << "mtcut view: wrote " << options.screenshot << "\n";
  } else {
    window.run();
  }
  session.attach_hid(nullptr);
  if (input) input->stop();
}

}  // namespace

void register_view_command(CLI::App& app) {
  auto options = std::make_shared<ViewOptions>();
  CLI::App* cmd = app.add_subcommand(
      "view",
      "Open the interactive viewer on a scenario: Shift + left drag cuts with the mouse, the panel shows frame "
      "times and settings. With --screenshot, play N frames without input, write a PNG and exit.\n"
      "  mtcut view\n"
      "  xvfb-run -a -s \"-screen 0 1280x720x24\" mtcut view config/scenarios/default.toml --frames 90 "
      "--screenshot out.png");
  cmd->add_option("scenario", options->scenario, "the scenario file (default: config/scenarios/default.toml)");
  cmd->add_option("--frames", options->frames, "play this many frames of the scenario before showing it")
      ->check(non_negative_number());
  cmd->add_option("--screenshot", options->screenshot, "write the last frame to this PNG and exit");
  cmd->add_option("--width", options->width, "window width in pixels")->check(CLI::Range(64, 8192));
  cmd->add_option("--height", options->height, "window height in pixels")->check(CLI::Range(64, 8192));
  cmd->add_flag("--hide-panel", options->hide_panel, "draw the scene without the panel");
  cmd->add_flag("--lod-colors", options->lod_colors, "colour faces by LOD level (blue finest, red coarsest)");
  cmd->add_flag("--wireframe", options->wireframe, "draw the mesh's edges over the surface");
  cmd->add_option("--hid", options->hid_profile,
                  "cut with a HID device (3D mouse, pen tablet, gamepad); PROFILE (config/hid or a .toml) defaults "
                  "to the one that fits a connected device. Give SCENARIO before it")
      ->expected(0, 1);
  cmd->add_option("--record-hid", options->record_hid, "with --hid: record the device's raw reports (.hidrec)");
  cmd->callback([options, cmd] {
    options->hid = cmd->count("--hid") > 0;
    run_view(*options);
  });
}

}  // namespace mtcut::app
