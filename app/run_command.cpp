#include "app/run_command.h"

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <iostream>
#include <numeric>
#include <sstream>

#include "app/json_report.h"
#include "engine/atomic_file.h"
#include "engine/input_error.h"
#include "engine/mt/mt_builder.h"
#include "engine/mt/mt_stats.h"
#include "sim/world.h"

namespace mtcut::app {
namespace {

using Clock = std::chrono::steady_clock;

// mean, median, 95th percentile and max of a series, in its unit.
nlohmann::ordered_json distribution(std::vector<double> values) {
  if (values.empty()) return nullptr;
  std::sort(values.begin(), values.end());
  const double mean = std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
  return {{"mean", mean},
          {"p50", values[values.size() / 2]},
          {"p95", values[std::min(values.size() - 1, values.size() * 95 / 100)]},
          {"max", values.back()}};
}

std::string hex(std::uint64_t v) {
  std::ostringstream s;
  s << std::hex << std::setw(16) << std::setfill('0') << v;
  return s.str();
}

}  // namespace

nlohmann::ordered_json run_scenario(const ScenarioDef& scenario, const RunOptions& options) {
  const auto start = Clock::now();
  const engine::LoadedMesh loaded = engine::load_mesh(scenario.mesh, scenario.mesh_load);
  if (const auto report = loaded.mesh.validate(); !report.ok())
    throw engine::InputError(scenario.mesh + ": invalid tet mesh: " + report.problems.front());
  engine::MtBuildReport build;
  engine::Mt mt = engine::build_mt(loaded.mesh, scenario.world.mt, &build);
  const engine::MtStats mt_stats = engine::compute_mt_stats(mt);
  const double setup_seconds = std::chrono::duration<double>(Clock::now() - start).count();

  sim::World world(std::move(mt), scenario.world);
  const int frames = options.frames_override > 0 ? options.frames_override : scenario.frames;
  std::vector<double> total_ms, cut_ms, lod_ms, physics_ms;
  std::vector<std::string> csv_rows;
  std::size_t min_tets = SIZE_MAX, max_tets = 0;
  int cg_iterations = 0;
  auto last_report = Clock::now();
  const auto run_start = Clock::now();
  for (int f = 0; f < frames; ++f) {
    const sim::FrameMetrics& m = world.step(scenario.scalpel.pose_at(world.time()));
    total_ms.push_back(m.total_ms);
    cut_ms.push_back(m.cut_ms);
    lod_ms.push_back(m.lod_ms);
    physics_ms.push_back(m.physics_ms);
    min_tets = std::min(min_tets, m.frontier_tets);
    max_tets = std::max(max_tets, m.frontier_tets);
    cg_iterations += m.cg_iterations;
    if (!scenario.frames_path.empty()) {
      std::ostringstream row;
      row << m.frame << "," << m.time << "," << m.cut_ms << "," << m.lod_ms << "," << m.physics_ms << ","
          << m.total_ms << "," << m.frontier_tets << "," << m.frontier_vertices << "," << m.springs << ","
          << m.lod_changes << "," << m.cg_iterations << "," << (m.step_refused ? 1 : 0);
      csv_rows.push_back(row.str());
    }
    if (options.progress && Clock::now() - last_report > std::chrono::seconds(1)) {
      std::cerr << "\rmtcut run: frame " << f + 1 << "/" << frames << std::flush;
      last_report = Clock::now();
    }
  }
  if (options.progress && std::chrono::duration<double>(Clock::now() - run_start).count() > 1) std::cerr << "\n";
  const double run_seconds = std::chrono::duration<double>(Clock::now() - run_start).count();

  const engine::ValidationReport valid = world.validate();
  nlohmann::ordered_json out;
  out["scenario"] = scenario.file;
  out["mesh"] = scenario.mesh;
  out["mt"] = {{"vertices", mt_stats.vertices},       {"tets_total", mt_stats.tets_total},
               {"fragments", mt_stats.fragments},     {"dag_depth", mt_stats.dag_depth},
               {"finest_tets", mt_stats.finest_tets}, {"coarsest_tets", mt_stats.coarsest_tets}};
  out["frames"] = frames;
  out["simulated_seconds"] = world.time();
  out["setup_seconds"] = setup_seconds;
  out["run_seconds"] = run_seconds;
  out["frame_ms"] = distribution(total_ms);
  out["cut_ms"] = distribution(cut_ms);
  out["lod_ms"] = distribution(lod_ms);
  out["physics_ms"] = distribution(physics_ms);
  out["frontier_tets"] = {{"min", min_tets}, {"max", max_tets}, {"final", world.frontier().tets().size()}};
  out["mean_cg_iterations"] = frames > 0 ? static_cast<double>(cg_iterations) / frames : 0.0;
  out["pieces"] = 1;
  out["nan_events"] = world.nan_events();
  out["valid"] = valid.ok();
  if (!valid.ok()) out["problems"] = valid.problems;
  out["state_hash"] = hex(world.state_hash());

  if (!scenario.summary_path.empty())
    engine::write_stream_atomically(scenario.summary_path, [&](std::ostream& s) { s << out.dump(2) << "\n"; });
  if (!scenario.frames_path.empty())
    engine::write_stream_atomically(scenario.frames_path, [&](std::ostream& s) {
      s << "frame,time,cut_ms,lod_ms,physics_ms,total_ms,frontier_tets,frontier_vertices,springs,lod_changes,"
           "cg_iterations,refused\n";
      for (const auto& row : csv_rows) s << row << "\n";
    });
  return out;
}

void register_run_command(CLI::App& app) {
  struct Options {
    std::string scenario;
    std::string summary;
    RunOptions run;
    bool json = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "run",
      "Play a scenario headless (TOML: organ, MT, material, LOD, cutter, integrator, scalpel keyframes) and report "
      "frame times, element counts, pieces and the state hash.\n"
      "  mtcut run config/scenarios/default.toml --json");
  cmd->add_option("scenario", options->scenario, "the scenario file (config/scenarios/*.toml)")->required();
  cmd->add_option("--frames", options->run.frames_override, "run this many frames instead of the scenario's")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--summary", options->summary, "write the summary JSON to this file (overrides [output] summary)");
  cmd->add_flag("--json", options->json, "print the summary as JSON");
  cmd->callback([options] {
    ScenarioDef scenario = load_scenario(options->scenario);
    if (!options->summary.empty()) scenario.summary_path = options->summary;
    const auto summary = run_scenario(scenario, options->run);
    if (options->json) {
      std::cout << summary.dump(2) << "\n";
    } else {
      print_human(std::cout, summary);
    }
  });
}

}  // namespace mtcut::app
