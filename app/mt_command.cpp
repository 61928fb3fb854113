#include "app/mt_command.h"

#include <chrono>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/cli_checks.h"
#include "app/json_report.h"
#include "app/mesh_input_options.h"
#include "engine/input_error.h"
#include "engine/mesh_loader.h"
#include "engine/mt/frontier.h"
#include "engine/mt/mt_builder.h"
#include "engine/mt/mt_presets.h"
#include "engine/mt/mt_stats.h"
#include "engine/stopwatch.h"

namespace mtcut::app {
namespace {

struct MtOptions {
  std::string input;
  std::string preset;
  engine::MeshLoadDef load;
  engine::MtBuildOptions build;
  MeshInputOptions mesh_input;
  bool no_preserve_boundary = false;
  bool skip_validation = false;
  bool json = false;
};

void run_mt(MtOptions& options) {
  std::string spec = options.input;
  if (!options.preset.empty()) {
    const engine::MtPreset preset = require_mt_preset(options.preset);
    if (spec.empty()) spec = preset.mesh_spec;
    options.load = preset.mesh;
    options.build = preset.build;
  }
  if (spec.empty()) throw engine::InputError("give a mesh (builtin:NAME or a file) or --preset");
  apply_mesh_input_options(options.mesh_input, options.load);
  if (options.no_preserve_boundary) options.build.preserve_boundary = false;

  const BuiltMt built = build_mt_from(spec, options.load, options.build);
  const engine::Mt& mt = built.mt;
  const engine::MtStats stats = engine::compute_mt_stats(mt);

  nlohmann::ordered_json out = {{"input", spec}};
  if (!options.preset.empty()) out["preset"] = options.preset;
  out["vertices"] = stats.vertices;
  out["tets_total"] = stats.tets_total;
  out["fragments"] = stats.fragments;
  out["dag_depth"] = stats.dag_depth;
  out["finest_tets"] = stats.finest_tets;
  out["coarsest_tets"] = stats.coarsest_tets;
  out["collapses"] = built.report.collapses;
  out["rounds"] = built.report.rounds;
  out["preserve_boundary"] = options.build.preserve_boundary;
  if (!options.build.preserve_boundary) {
    if (std::isfinite(options.build.max_surface_deviation))
      out["max_surface_deviation"] = options.build.max_surface_deviation;
    out["coarsest_surface_deviation"] = stats.coarsest_surface_deviation;
  }
  out["megabytes"] = static_cast<double>(stats.bytes) / (1024.0 * 1024.0);
  out["mesh_seconds"] = built.mesh_seconds;
  out["build_seconds"] = built.build_seconds;
  if (!options.skip_validation) {
    const auto start = std::chrono::steady_clock::now();
    const engine::ValidationReport report = mt.validate();
    out["valid"] = report.ok();
    out["validate_seconds"] = engine::seconds_since(start);
    if (!report.ok()) out["problems"] = report.problems;
  }
  print_report(std::cout, out, options.json);
  if (out.contains("valid") && !out["valid"].get<bool>())
    throw engine::InputError(spec + ": the MT built is not valid (an internal error; please report it)");
}

}  // namespace

engine::MtPreset require_mt_preset(const std::string& name) {
  const auto preset = engine::find_mt_preset(name);
  if (!preset) throw engine::InputError("--preset " + name + ": unknown preset (known: paper)");
  return *preset;
}

BuiltMt build_mt_from(const std::string& spec, const engine::MeshLoadDef& load, const engine::MtBuildOptions& build) {
  auto start = std::chrono::steady_clock::now();
  const engine::LoadedMesh loaded = load_input_mesh(spec, load);
  const double mesh_seconds = engine::seconds_since(start);
  BuiltMt built;
  start = std::chrono::steady_clock::now();
  built.mt = engine::build_mt(loaded.mesh, build, &built.report);
  built.build_seconds = engine::seconds_since(start);
  built.mesh_seconds = mesh_seconds;
  return built;
}

BuiltMt build_preset_mt(const std::string& name) {
  const engine::MtPreset preset = require_mt_preset(name);
  return build_mt_from(preset.mesh_spec, preset.mesh, preset.build);
}

void register_mt_command(CLI::App& app) {
  auto options = std::make_shared<MtOptions>();
  CLI::App* cmd = app.add_subcommand(
      "mt",
      "Build the multiresolution model (Multi-Tessellation) of a mesh by half-edge collapses; validate it; print its "
      "figures.\n"
      "  mtcut mt ../shared/meshes/liver2.obj --json\n"
      "  mtcut mt --preset paper --json");
  cmd->add_option("input", options->input, "builtin:NAME, a surface to mesh, or a tet mesh file (as for `mtcut mesh`)");
  cmd->add_option("--preset", options->preset, "a named configuration: paper (the paper's Table 1 MT size)");
  cmd->add_option("--target-coarsest", options->build.target_coarsest_tets,
                  "stop simplifying at this many tets (0: as far as valid collapses go)")
      ->capture_default_str();
  cmd->add_option("--collapses-per-fragment", options->build.collapses_per_fragment,
                  "neighbouring collapses grouped into one fragment")
      ->capture_default_str()
      ->check(positive_number());
  cmd->add_flag("--no-preserve-boundary", options->no_preserve_boundary,
                "let collapses move the surface (by at most their error and --max-surface-deviation)");
  cmd->add_option("--max-surface-deviation", options->build.max_surface_deviation,
                  "with --no-preserve-boundary: how far the surface may move in all, as a fraction of the mesh's "
                  "bounding-box diagonal")
      ->capture_default_str()
      ->check(positive_number());
  add_mesh_input_options(*cmd, options->load, options->mesh_input);
  cmd->add_flag("--no-validate", options->skip_validation, "skip MT::validate() (large meshes)");
  cmd->add_flag("--json", options->json, "print one JSON object");
  cmd->callback([options] { run_mt(*options); });
}

}  // namespace mtcut::app
