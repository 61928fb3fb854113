#pragma once
// `mtcut cut IN --polygon "x,y,z;..." [--scheme lut|bielser17] [--snap F]
// [-o OUT] [--json]`: cuts a single-resolution tet mesh by one planar convex
// polygon, writes the result, and prints what the cut did.

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cut/mesh_cutter.h"

namespace mtcut::app {

void register_cut_command(CLI::App& app);

// The cut's figures under the command's key names: split_tets, new_tets,
// new_tets_per_split_tet, cases {A..O, vertex}, pieces, min_dihedral_deg
// (null when nothing was split), new_vertices, seconds.
nlohmann::ordered_json cut_stats_json(const cut::CutStats& stats);

}  // namespace mtcut::app
