#include "app/bench_command.h"

#include <iostream>

#include "app/bench_sim.h"
#include "app/json_report.h"

namespace mtcut::app {
namespace {

void print(const nlohmann::ordered_json& report, bool json) {
  if (json) {
    std::cout << report.dump(2) << "\n";
  } else {
    std::cout << report.dump(2) << "\n";  // nested figures read best as indented JSON
  }
}

}  // namespace

void register_bench_command(CLI::App& app) {
  CLI::App* bench = app.add_subcommand("bench", "Performance figures as JSON (median of timed batches after a warm-up)");
  bench->require_subcommand(1);

  auto sim_def = std::make_shared<SimBenchDef>();
  auto json = std::make_shared<bool>(false);
  CLI::App* sim = bench->add_subcommand(
      "sim", "Spring step on a builtin box (~10k vertices, ~60k springs): symplectic Euler, implicit Euler at 1/60 s, "
             "and a plain SoA reference loop");
  sim->add_option("--tets", sim_def->tets, "target tet count of the box")->capture_default_str()->check(CLI::PositiveNumber);
  sim->add_option("--runs", sim_def->runs, "timed batches (median reported)")->capture_default_str()->check(CLI::PositiveNumber);
  sim->add_flag("--json", *json, "print JSON (the default output is JSON as well)");
  sim->callback([sim_def, json] { print(run_sim_bench(*sim_def), *json); });
}

}  // namespace mtcut::app
