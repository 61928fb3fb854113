#include "app/bench_command.h"

#include <iostream>

#include "app/bench_cut.h"
#include "app/bench_sim.h"
#include "app/bench_stroke.h"
#include "app/bench_table1.h"
#include "app/cli_checks.h"
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
  sim->add_option("--tets", sim_def->tets, "target tet count of the box")->capture_default_str()->check(positive_number());
  sim->add_option("--runs", sim_def->runs, "timed runs, median reported (each implicit run replays the same 3 s from rest)")
      ->capture_default_str()
      ->check(positive_number());
  sim->add_flag("--json", *json, "print JSON (the default output is JSON as well)");
  sim->callback([sim_def, json] { print(run_sim_bench(*sim_def), *json); });

  auto cut_def = std::make_shared<CutBenchDef>();
  CLI::App* cut = bench->add_subcommand(
      "cut", "The single-resolution cutter, LUT and 1:17, on the same complete and partial planar cuts of the real "
             "liver (liver2.obj) and the builtin organ: split and new tets, ns per split tet, their ratio");
  cut->add_option("--mesh", cut_def->liver, "the real mesh to cut instead of ../shared/meshes/liver2.obj");
  cut->add_option("--organ", cut_def->organ, "the second mesh: builtin:NAME or a file")->capture_default_str();
  cut->add_option("--tets", cut_def->organ_tets, "target tet count of a builtin organ")
      ->capture_default_str()
      ->check(positive_number());
  cut->add_option("--runs", cut_def->runs, "timed runs, each cut on a fresh copy (median reported)")
      ->capture_default_str()
      ->check(positive_number());
  cut->add_flag("--json", *json, "print JSON (the default output is JSON as well)");
  cut->callback([cut_def, json] { print(run_cut_bench(*cut_def), *json); });

  auto table1_def = std::make_shared<Table1BenchDef>();
  CLI::App* table1 = bench->add_subcommand(
      "table1", "The paper's Table 1 on the --preset paper MT: five planar cuts of growing size, the last one "
                "separating the object; split and DAG update times beside the paper's");
  table1->add_option("--runs", table1_def->runs, "timed runs per row, each on a fresh copy of the MT (median reported)")
      ->capture_default_str()
      ->check(positive_number());
  table1->add_option("--markdown", table1_def->markdown, "also write the table as markdown, with the machine");
  table1->add_flag("--json", *json, "print JSON (the default output is JSON as well)");
  table1->callback([table1_def, json] { print(run_table1_bench(*table1_def), *json); });

  auto stroke_def = std::make_shared<StrokeBenchDef>();
  CLI::App* stroke = bench->add_subcommand(
      "stroke", "Progressive cutting: four scalpel strokes (straight, curved, L-turn, tip inside) on the builtin organ "
                "and the real liver, cut once and in 60, 240 and 1,000 steps: new tets against the one-polygon cut, "
                "per-step cut time, pieces");
  stroke->add_option("--mesh", stroke_def->liver, "the real mesh instead of ../shared/meshes/liver2.obj");
  stroke->add_option("--tets", stroke_def->organ_tets, "target tet count of the builtin organ")
      ->capture_default_str()
      ->check(positive_number());
  stroke->add_option("--steps", stroke_def->steps, "step counts of the progressive cuts")->capture_default_str();
  stroke->add_option("--runs", stroke_def->runs, "runs per stroke and step count (median of each figure)")
      ->capture_default_str()
      ->check(positive_number());
  stroke->add_option("--strokes", stroke_def->strokes, "the strokes to cut (default: all)")
      ->check(CLI::IsMember({"straight", "curved", "l_turn", "tip_inside"}));
  stroke->add_flag("--json", *json, "print JSON (the default output is JSON as well)");
  stroke->callback([stroke_def, json] { print(run_stroke_bench(*stroke_def), *json); });
}

}  // namespace mtcut::app
