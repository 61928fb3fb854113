#pragma once
// `mtcut bench sim`: the spring step on a builtin box of ~10k vertices /
// ~60k springs, gravity, one face fixed; each integrator and a plain SoA
// reference loop (the ceiling) measured in the same run.

#include <nlohmann/json.hpp>

namespace mtcut::app {

struct SimBenchDef {
  int tets = 50000;   // builtin box target (~10k vertices, ~60k springs)
  int runs = 5;       // timed runs (median reported), after a warm-up run
  int steps = 200;    // explicit steps per run
  int frames = 180;   // implicit 1/60 s frames per run, from rest (3 s)
};

nlohmann::ordered_json run_sim_bench(const SimBenchDef& def);

}  // namespace mtcut::app
