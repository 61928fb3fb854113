#pragma once
// Reports as JSON (one object, stable key names) or as aligned text lines.

#include <nlohmann/json.hpp>
#include <ostream>

#include "engine/mesh_stats.h"

namespace mtcut::app {

nlohmann::ordered_json to_json(const engine::MeshStats& stats);

// Prints a flat JSON object as "key: value" lines for people.
void print_human(std::ostream& out, const nlohmann::ordered_json& report);

// One JSON line when `json`, else print_human: how `mtcut mesh`, `mt` and
// `cut` print their report.
void print_report(std::ostream& out, const nlohmann::ordered_json& report, bool json);

}  // namespace mtcut::app
