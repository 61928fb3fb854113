#include "app/scenario.h"

#include <filesystem>

#include "app/material_file.h"
#include "app/mesh_input_options.h"
#include "app/toml_table.h"
#include "engine/builtin_shapes.h"
#include "engine/input_error.h"
#include "engine/mesh_loader.h"
#include "sim/scalpel_trace.h"

namespace mtcut::app {
namespace {
namespace fs = std::filesystem;

void read_mesh(TomlTable& t, const std::string& scenario_dir, ScenarioDef& s) {
  const toml::node* source = t.node("source");
  if (!source || !source->is_string()) t.fail(source, "'mesh.source' must name builtin:SHAPE or a mesh file");
  s.mesh = source->value<std::string>().value();
  if (!engine::parse_builtin(s.mesh) && fs::path(s.mesh).is_relative()) s.mesh = (fs::path(scenario_dir) / s.mesh).string();
  if (!engine::parse_builtin(s.mesh) && !fs::exists(s.mesh)) t.fail(source, "mesh file '" + s.mesh + "' does not exist");
  t.read("tets", s.mesh_load.builtin_tets);
  t.read("size", s.mesh_load.builtin_size);
  t.read("max_volume", s.mesh_load.meshing.max_volume);
  t.read("quality", s.mesh_load.meshing.radius_edge_ratio);
  t.read("strict", s.mesh_load.strict);
  if (s.mesh_load.builtin_tets < 1) t.fail(t.node("tets"), "'mesh.tets' must be at least 1");
  // The file's length unit, by name or in metres; everything else in a scenario is in metres.
  if (t.node("units") && t.node("scale")) t.fail(t.node("scale"), "give 'mesh.units' or 'mesh.scale', not both");
  if (auto units = t.string("units")) {
    try {
      set_mesh_units(*units, "'mesh.units'", s.mesh_load);
    } catch (const engine::InputError& e) {
      t.fail(t.node("units"), e.what());
    }
  }
  if (t.node("scale")) {
    t.read("scale", s.mesh_load.metres_per_unit);
    if (!(s.mesh_load.metres_per_unit > 0)) t.fail(t.node("scale"), "'mesh.scale' must be a positive number of metres");
    s.mesh_load.unit_stated = true;
  }
  t.finish();
}

void read_mt(TomlTable& t, engine::MtBuildOptions& mt) {
  if (auto v = t.integer("target_coarsest_tets")) {
    if (*v < 0) t.fail(t.node("target_coarsest_tets"), "'mt.target_coarsest_tets' must be >= 0");
    mt.target_coarsest_tets = static_cast<std::size_t>(*v);
  }
  t.read("preserve_boundary", mt.preserve_boundary);
  t.read("max_surface_deviation", mt.max_surface_deviation);
  if (!(mt.max_surface_deviation > 0))
    t.fail(t.node("max_surface_deviation"),
           "'mt.max_surface_deviation' must be a positive fraction of the mesh's bounding-box diagonal");
  t.read("collapses_per_fragment", mt.collapses_per_fragment);
  t.finish();
}

void read_material_section(TomlTable& t, sim::MaterialDef& material) {
  if (auto preset = t.string("preset")) {
    try {
      material = load_material(*preset);
    } catch (const engine::InputError& e) {
      t.fail(t.node("preset"), e.what());
    }
  }
  read_material(t, material);  // keys given here override the preset
  t.finish();
}

void read_fixed(TomlTable& t, sim::FixedRegion& fixed) {
  const std::string kind = t.string("kind").value_or("none");
  if (kind == "none") {
    fixed.kind = sim::FixedRegion::Kind::kNone;
  } else if (kind == "box") {
    fixed.kind = sim::FixedRegion::Kind::kBox;
    t.read("min", fixed.box_min);
    t.read("max", fixed.box_max);
  } else if (kind == "half_space") {
    fixed.kind = sim::FixedRegion::Kind::kHalfSpace;
    t.read("normal", fixed.normal);
    t.read("offset", fixed.offset);
    if (fixed.normal.norm() == 0) t.fail(t.node("normal"), "'fixed.normal' must not be zero");
    fixed.offset /= fixed.normal.norm();
    fixed.normal.normalize();
  } else if (kind == "list") {
    fixed.kind = sim::FixedRegion::Kind::kList;
    const toml::node* list = t.node("vertices");
    const toml::array* a = list ? list->as_array() : nullptr;
    if (!a) t.fail(list, "'fixed.vertices' must be an array of vertex ids");
    for (const auto& item : *a) {
      if (!item.is_integer() || item.value<std::int64_t>().value() < 0) t.fail(&item, "vertex ids must be integers >= 0");
      fixed.vertices.emplace_back(static_cast<std::int32_t>(item.value<std::int64_t>().value()));
    }
    std::sort(fixed.vertices.begin(), fixed.vertices.end());
  } else {
    t.fail(t.node("kind"), "'fixed.kind' must be none, box, half_space or list");
  }
  t.finish();
}

void read_environment(TomlTable& t, sim::Environment& env) {
  t.read("gravity", env.gravity);
  if (auto height = t.number("floor_height")) env.floor = sim::Plane{-env.gravity.normalized(), *height};
  t.read("floor_friction", env.floor_friction);
  if (env.floor_friction < 0 || env.floor_friction > 1)
    t.fail(t.node("floor_friction"), "'environment.floor_friction' must be between 0 and 1");
  t.finish();
}

void read_lod(TomlTable& t, sim::LodDef& lod) {
  t.read("enabled", lod.enabled);
  t.read("near_radius", lod.near_radius);
  t.read("near_error", lod.near_error);
  t.read("far_radius", lod.far_radius);
  t.read("far_error", lod.far_error);
  t.read("background_build", lod.background_build);
  t.read("build_frames", lod.build_frames);
  if (lod.build_frames < 1) t.fail(t.node("build_frames"), "'lod.build_frames' must be at least 1");
  if (lod.near_radius < 0 || lod.far_radius < lod.near_radius)
    t.fail(nullptr, "[lod]: need 0 <= near_radius <= far_radius");
  if (lod.near_error < 0 || lod.far_error < lod.near_error) t.fail(nullptr, "[lod]: need 0 <= near_error <= far_error");
  t.finish();
}

void read_cutter(TomlTable& t, sim::CutBudgetDef& budget) {
  const auto tets = t.number("budget_tets");
  const auto ms = t.number("budget_ms");
  if (tets && ms) t.fail(t.node("budget_ms"), "[cutter]: give budget_tets or budget_ms, not both");
  if (tets) budget = {sim::CutBudgetDef::Unit::kTets, *tets};
  if (ms) budget = {sim::CutBudgetDef::Unit::kMilliseconds, *ms};
  if (!(budget.amount > 0)) t.fail(nullptr, "[cutter]: the budget must be positive");
  t.finish();
}

void read_integrator(TomlTable& t, sim::IntegratorDef& integrator) {
  if (auto kind = t.string("kind")) {
    if (*kind == "implicit") {
      integrator.kind = sim::IntegratorKind::kImplicitEuler;
    } else if (*kind == "symplectic") {
      integrator.kind = sim::IntegratorKind::kSymplecticEuler;
    } else {
      t.fail(t.node("kind"), "'integrator.kind' must be implicit or symplectic");
    }
  }
  t.read("substeps", integrator.substeps);
  t.read("cg_tolerance", integrator.cg_tolerance);
  t.read("cg_max_iterations", integrator.cg_max_iterations);
  if (integrator.substeps < 1) t.fail(t.node("substeps"), "'integrator.substeps' must be at least 1");
  if (!(integrator.cg_tolerance > 0)) t.fail(t.node("cg_tolerance"), "'integrator.cg_tolerance' must be positive");
  t.finish();
}

// A recorded trace (sim/scalpel_trace.h), relative to the scenario's folder.
sim::ScalpelPath read_scalpel_trace_key(TomlTable& t, const std::string& scenario_dir, ScenarioDef& s) {
  const toml::node* trace = t.node("trace");
  if (!trace->is_string()) t.fail(trace, "'scalpel.trace' must name a trace file (.csv)");
  s.scalpel_trace = trace->value<std::string>().value();
  if (fs::path(s.scalpel_trace).is_relative()) s.scalpel_trace = (fs::path(scenario_dir) / s.scalpel_trace).string();
  std::error_code ec;
  if (!fs::is_regular_file(s.scalpel_trace, ec)) t.fail(trace, "trace file '" + s.scalpel_trace + "' does not exist");
  if (!t.tables("keyframes").empty()) t.fail(trace, "[scalpel]: give keyframes or a trace, not both");
  t.finish();
  return sim::read_scalpel_trace(s.scalpel_trace);
}

sim::ScalpelPath read_scalpel(TomlTable& t, const std::string& scenario_dir, ScenarioDef& s) {
  if (t.node("trace")) return read_scalpel_trace_key(t, scenario_dir, s);
  std::vector<sim::ScalpelKeyframe> keys;
  for (TomlTable& k : t.tables("keyframes")) {
    sim::ScalpelKeyframe key;
    const toml::node* time = k.node("time");
    if (!time || !time->is_number()) k.fail(time, "each keyframe needs a 'time' (s)");
    key.time = time->value<double>().value();
    if (!keys.empty() && !(key.time > keys.back().time)) k.fail(time, "keyframe times must increase");
    const auto base = k.vec3("base");
    const auto tip = k.vec3("tip");
    if (!base || !tip) k.fail(nullptr, "each keyframe needs 'base' and 'tip' ([x, y, z] in metres)");
    key.pose.base = *base;
    key.pose.tip = *tip;
    k.read("engaged", key.pose.engaged);
    k.finish();
    keys.push_back(key);
  }
  if (keys.empty()) t.fail(nullptr, "[scalpel] needs at least one [[scalpel.keyframes]] or a trace");
  t.finish();
  return sim::ScalpelPath(std::move(keys));
}

}  // namespace

ScenarioDef load_scenario(const std::string& path) {
  const toml::table root = parse_toml_file(path);
  TomlTable top(root, path);
  ScenarioDef s;
  s.file = path;
  const std::string dir = fs::path(path).parent_path().string();

  auto mesh = top.table("mesh");
  if (!mesh) top.fail(nullptr, "the scenario needs a [mesh] section");
  read_mesh(*mesh, dir, s);
  if (auto t = top.table("mt")) read_mt(*t, s.world.mt);
  if (auto t = top.table("material")) read_material_section(*t, s.world.material);
  if (auto t = top.table("fixed")) read_fixed(*t, s.world.fixed);
  if (auto t = top.table("environment")) read_environment(*t, s.world.environment);
  if (auto t = top.table("lod")) read_lod(*t, s.world.lod);
  if (auto t = top.table("cutter")) read_cutter(*t, s.world.cut_budget);
  if (auto t = top.table("integrator")) read_integrator(*t, s.world.integrator);
  auto scalpel = top.table("scalpel");
  if (!scalpel) top.fail(nullptr, "the scenario needs a [scalpel] section with keyframes or a trace");
  s.scalpel = read_scalpel(*scalpel, dir, s);
  if (auto run = top.table("run")) {
    run->read("frames", s.frames);
    run->read("dt", s.world.dt);
    run->read("tool_radius", s.world.tool_radius);
    if (s.frames < 1) run->fail(run->node("frames"), "'run.frames' must be at least 1");
    if (!(s.world.dt > 0)) run->fail(run->node("dt"), "'run.dt' must be positive");
    if (s.world.tool_radius < 0) run->fail(run->node("tool_radius"), "'run.tool_radius' must be >= 0");
    run->finish();
  }
  if (auto out = top.table("output")) {
    out->read("summary", s.summary_path);
    out->read("frames", s.frames_path);
    out->read("snapshot_every", s.snapshot_every);
    if (s.snapshot_every < 0) out->fail(out->node("snapshot_every"), "'output.snapshot_every' must be >= 0");
    std::string surface = "finest";
    out->read("surface", surface);
    if (surface == "finest")
      s.surface = SurfaceKind::kFinest;
    else if (surface == "frontier")
      s.surface = SurfaceKind::kFrontier;
    else
      out->fail(out->node("surface"), "'output.surface' must be \"finest\" or \"frontier\"");
    out->finish();
  }
  top.finish();
  return s;
}

}  // namespace mtcut::app
