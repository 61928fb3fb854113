#include "app/run_command.h"

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>
#include <set>

#include "app/cli_checks.h"
#include "app/material_file.h"
#include "app/mesh_input_options.h"
#include "app/run_interrupt.h"
#include "app/run_metrics.h"
#include "app/run_progress.h"
#include "app/run_snapshots.h"
#include "app/run_summary.h"
#include "engine/atomic_file.h"
#include "engine/input_error.h"
#include "engine/mt/mt_builder.h"
#include "engine/mt/mt_stats.h"
#include "engine/stopwatch.h"
#include "sim/scalpel_trace.h"
#include "sim/world.h"

namespace mtcut::app {
namespace {
namespace fs = std::filesystem;

using Clock = std::chrono::steady_clock;

void make_out_dir(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) throw engine::InputError(dir.string() + ": cannot create the output folder");
}

// Every place the summary goes: DIR/summary.json, the scenario's [output]
// summary (relative to DIR) and --summary (relative to the working folder).
std::set<fs::path> summary_paths(const fs::path& dir, const std::string& scenario_summary) {
  std::set<fs::path> paths{(dir / "summary.json").lexically_normal()};
  if (!scenario_summary.empty()) paths.insert((dir / scenario_summary).lexically_normal());
  return paths;
}

}  // namespace

engine::Mt build_organ_mt(const ScenarioDef& scenario) {
  const engine::LoadedMesh loaded = load_input_mesh(scenario.mesh, scenario.mesh_load);
  return engine::build_mt(loaded.mesh, scenario.world.mt);
}

std::unique_ptr<sim::World> start_organ_world(const ScenarioDef& scenario, engine::Mt mt, const sim::WorldDef& def,
                                              const std::optional<sim::ScalpelPose>& blade) {
  try {
    return std::make_unique<sim::World>(std::move(mt), def, blade);
  } catch (const engine::InputError& e) {
    throw engine::InputError(scenario.mesh + ": " + e.what(), e.hint());
  }
}

std::string default_scenario_path() { return config_dir() + "/scenarios/default.toml"; }

std::string default_out_dir(const std::string& scenario_path) {
  return (fs::path("out") / fs::path(scenario_path).stem()).string();
}

RunResult run_scenario(const ScenarioDef& scenario, const RunOptions& options) {
  // Checked before the run, so a typo does not cost the run's trace at its end.
  if (!options.record_path.empty()) {
    const fs::path folder = fs::absolute(options.record_path).parent_path();
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
      throw engine::InputError(options.record_path + ": cannot record the trace there (no folder " + folder.string() +
                               ")");
  }
  std::optional<RunHid> hid;
  if (options.hid.enabled()) hid.emplace(options.hid, scenario.world.dt);
  const InterruptGuard interrupt;
  const auto setup_start = Clock::now();
  engine::Mt mt = build_organ_mt(scenario);
  RunRecord record;
  record.mt_stats = engine::compute_mt_stats(mt);
  record.setup_seconds = engine::seconds_since(setup_start);
  // Made once the inputs are known good: a bad mesh leaves no folder behind.
  const fs::path dir = options.out_dir.empty() ? fs::path(default_out_dir(scenario.file)) : fs::path(options.out_dir);
  make_out_dir(dir);

  // The blade's first pose, known now for a scripted path and a replay (not a live device).
  const std::optional<sim::ScalpelPose> blade = hid ? hid->start_pose() : scenario.scalpel.pose_at(0.0);
  const std::unique_ptr<sim::World> started = start_organ_world(scenario, std::move(mt), scenario.world, blade);
  sim::World& world = *started;
  if (hid) hid->start();  // last: a live input's clock starts with the World's time at 0
  const int frames = options.frames_override > 0 ? options.frames_override : scenario.frames;
  record.frames_requested = frames;
  const int every = scenario.snapshot_every;
  SnapshotSeries snapshots(dir.string(), world.mt().num_vertices(), scenario.surface);
  std::vector<MetricsRow> rows;
  std::vector<sim::ScalpelSample> samples;
  rows.reserve(static_cast<std::size_t>(frames));

  // The scalpel's samples for the frame at t, the last one at t: every sample
  // since the last frame of the HID or of a replayed trace (a fast stroke is a
  // polyline of poses), the one pose at t of keyframes (interpolated per frame).
  double previous_t = -std::numeric_limits<double>::infinity();
  const auto frame_samples = [&](double t) -> std::vector<sim::ScalpelSample> {
    if (hid) return hid->frame_samples(t);
    if (!scenario.scalpel_trace.empty()) return scenario.scalpel.samples_between(previous_t, t);
    return {{t, scenario.scalpel.pose_at(t)}};
  };

  const auto run_start = Clock::now();
  {
    ProgressBar progress(frames, options.progress);
    if (every > 0 && !interrupt.requested()) snapshots.write(world);
    for (int f = 0; f < frames && !interrupt.requested(); ++f) {
      const double t = world.time();
      const std::vector<sim::ScalpelSample> frame = frame_samples(t);
      previous_t = t;
      if (!options.record_path.empty()) samples.insert(samples.end(), frame.begin(), frame.end());
      world.step(sim::poses_of(frame));
      if (hid) {
        hid->stepped(t, world.last_frame().total_ms * 1e-3);
        hid->report_events(std::cerr);
      }
      rows.push_back(record_frame(world));
      if (every > 0 && world.frame() % static_cast<std::uint64_t>(every) == 0) snapshots.write(world);
      progress.update(f + 1, rows.back().frame.total_ms);
    }
    // The series ends with the last state, also when the run stopped early.
    if (every > 0 && snapshots.last_frame() != static_cast<std::int64_t>(world.frame())) snapshots.write(world);
  }
  record.run_seconds = engine::seconds_since(run_start);
  record.interrupted = interrupt.requested();
  record.rows = rows;

  write_metrics_csv((dir / "metrics.csv").string(), rows);
  if (!scenario.frames_path.empty()) write_stage_csv((dir / scenario.frames_path).string(), rows);
  write_deformed_surface(world, (dir / "surface.obj").string(), scenario.surface);
  if (!options.record_path.empty()) sim::write_scalpel_trace(options.record_path, samples);

  RunResult result;
  result.interrupted = record.interrupted;
  result.summary = summarize_run(scenario, record, world);
  nlohmann::ordered_json outputs = {{"dir", dir.string()},
                                    {"metrics", "metrics.csv"},
                                    {"summary", "summary.json"},
                                    {"snapshots", snapshots.count()},
                                    {"pvd", every > 0 ? SnapshotSeries::kCollection : ""},
                                    {"surface_pvd", every > 0 && snapshots.writes_surface() ? SnapshotSeries::kSurfaceCollection : ""},
                                    {"surface", "surface.obj"}};
  if (!options.record_path.empty()) outputs["trace"] = options.record_path;
  if (hid) result.summary["hid"] = hid->summary();
  result.summary["outputs"] = outputs;
  for (const fs::path& path : summary_paths(dir, scenario.summary_path))
    engine::write_stream_atomically(path.string(), [&](std::ostream& s) { s << result.summary.dump(2) << "\n"; });
  return result;
}

void register_run_command(CLI::App& app) {
  struct Options {
    std::string scenario;
    std::string summary;
    RunOptions run;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  auto replay_profile = std::make_shared<std::string>();  // --profile, for --hid-replay
  CLI::App* cmd = app.add_subcommand(
      "run",
      "Play a scenario headless (TOML: organ, MT, material, LOD, cutter, integrator, scalpel keyframes or trace) and "
      "write into the output folder: metrics.csv (one row per frame), summary.json, .vtu snapshots with a .pvd "
      "collection ([output] snapshot_every), surface.obj (the final deformed surface). Ctrl-C stops after the "
      "current frame, writes the outputs of the frames done and exits with 130.\n"
      "  mtcut run config/scenarios/liver.toml --frames 60 --out out/liver --record liver_trace.csv");
  cmd->add_option("scenario", options->scenario,
                  "the scenario file (config/scenarios/*.toml); default: the built-in default scenario, " +
                      default_scenario_path());
  cmd->add_option("--frames", options->run.frames_override, "run this many frames instead of the scenario's")
      ->check(positive_number());
  cmd->add_option("--out", options->run.out_dir,
                  "the output folder (made if missing); default: out/<scenario file name without .toml>");
  cmd->add_option("--record", options->run.record_path,
                  "write the scalpel samples of the run to this trace file (CSV, see README)");
  cmd->add_option("--hid", options->run.hid.profile,
                  "cut with a HID device (3D mouse, pen tablet, gamepad), live, for the scenario's frames in real "
                  "time; PROFILE (config/hid or a .toml) defaults to the one that fits a connected device. Give "
                  "SCENARIO before it")
      ->expected(0, 1);
  cmd->add_option("--record-hid", options->run.hid.record_path,
                  "with --hid: record the device's raw reports to this file (.hidrec)");
  cmd->add_option("--hid-replay", options->run.hid.replay_path,
                  "replay a raw recording (.hidrec) through the HID decoder as the scalpel");
  cmd->add_option("--profile", *replay_profile,
                  "with --hid-replay: the profile to decode the recording with (default: the one it names)");
  cmd->add_option("--summary", options->summary, "also write the summary JSON to this file");
  cmd->add_flag("--json", options->json, "print the summary as JSON instead of a paragraph");
  cmd->callback([options, cmd, replay_profile] {
    options->run.hid.live = cmd->count("--hid") > 0;
    if (!replay_profile->empty()) {
      if (options->run.hid.replay_path.empty())
        throw engine::InputError("--profile " + *replay_profile + ": goes with --hid-replay (with --hid: --hid " +
                                 *replay_profile + ")");
      options->run.hid.profile = *replay_profile;
    }
    const ScenarioDef scenario = load_scenario(options->scenario.empty() ? default_scenario_path() : options->scenario);
    const RunResult result = run_scenario(scenario, options->run);
    if (!options->summary.empty())
      engine::write_stream_atomically(options->summary, [&](std::ostream& s) { s << result.summary.dump(2) << "\n"; });
    if (options->json) {
      std::cout << result.summary.dump(2) << "\n";
    } else {
      print_run_paragraph(std::cout, result.summary);
    }
    if (result.interrupted) {
      std::cout.flush();
      std::exit(kInterruptedExitCode);
    }
  });
}

}  // namespace mtcut::app
