#pragma once
// `mtcut bench stroke`: progressive cutting (DESIGN.md, "Progressive
// cutting") against the one-polygon cut of the same stroke. Four strokes
// (straight through, curved, an L-turn, the tip inside the tissue) on the
// builtin organ of the default scenario and the real liver
// (../shared/meshes/liver2.obj meshed by TetGen), each cut once at the end
// (all its poses in one frame: each straight part one polygon) and
// progressively in 60, 240 and 1,000 steps (a pose a step, the part in
// progress cut provisionally at every step). Per stroke and step count:
// new_tets, tets_ratio_vs_one_polygon, the per-step cut time p50/p99/max
// (retraction, recut and DAG update of a step; medians of --runs runs) and
// pieces.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace mtcut::app {

struct StrokeBenchDef {
  std::string liver;  // the real mesh (empty: liver2.obj among the shared meshes)
  int organ_tets = 8000;  // target tets of the builtin organ (and of a builtin given as the real mesh)
  std::vector<int> steps{60, 240, 1000};
  int runs = 3;  // timed runs per stroke and step count (median of each figure)
  std::vector<std::string> strokes;  // the strokes to cut, by name (empty: all four)
};

// Throws InputError for a bad mesh.
nlohmann::ordered_json run_stroke_bench(const StrokeBenchDef& def);

}  // namespace mtcut::app
