#include "app/mesh_input_options.h"

#include <unistd.h>

#include <iostream>

#include "app/cli_checks.h"
#include "engine/input_error.h"

namespace mtcut::app {

void add_mesh_input_options(CLI::App& cmd, engine::MeshLoadDef& load, MeshInputOptions& options) {
  cmd.add_option("--tets", load.builtin_tets, "target tet count of a builtin shape")
      ->capture_default_str()
      ->check(positive_number());
  cmd.add_option("--size", options.size, "extents x,y,z of a builtin shape in metres")->delimiter(',');
  cmd.add_option("--max-volume", load.meshing.max_volume,
                 "largest tet volume in m^3 when meshing a surface (0 = none)")
      ->check(non_negative_number());
  CLI::Option* units =
      cmd.add_option("--units", options.units, "the mesh file's length unit: m (default), dm, cm or mm");
  CLI::Option* scale =
      cmd.add_option("--scale", options.scale, "the mesh file's length unit in metres (0.001 for millimetres)")
          ->check(positive_number());
  units->excludes(scale);
  cmd.add_flag("--strict", load.strict,
               "refuse a surface that is open, non-manifold or crosses itself instead of repairing it");
}

void set_mesh_units(const std::string& units, const std::string& where, engine::MeshLoadDef& load) {
  const auto metres = engine::metres_per_unit(units);
  if (!metres) throw engine::InputError(where + " '" + units + "': unknown unit (known: m, dm, cm, mm)");
  load.metres_per_unit = *metres;
  load.unit_stated = true;
}

void apply_mesh_input_options(const MeshInputOptions& options, engine::MeshLoadDef& load) {
  if (!options.size.empty()) {
    if (options.size.size() != 3) throw engine::InputError("--size: give three extents x,y,z");
    load.builtin_size = engine::Vec3(options.size[0], options.size[1], options.size[2]);
  }
  if (!options.units.empty()) set_mesh_units(options.units, "--units", load);
  if (options.scale > 0) {
    load.metres_per_unit = options.scale;
    load.unit_stated = true;
  }
}

std::string add_advice(const std::string& line, const engine::InputHint& hint) {
  switch (hint.kind) {
    case engine::InputHint::Kind::kNone: return line;
    case engine::InputHint::Kind::kUnits: {
      if (hint.unit.empty())
        return line + "; give the file's unit with --units or --scale, or [mesh] units or scale in a scenario";
      const std::string unit(hint.unit);
      return line + "; if so, say --units " + unit + ", or [mesh] units = \"" + unit + "\" in a scenario";
    }
    case engine::InputHint::Kind::kMaxVolume: return line + "; raise --max-volume, or [mesh] max_volume in a scenario";
  }
  return line;
}

engine::LoadedMesh load_input_mesh(const std::string& spec, engine::MeshLoadDef load) {
  bool shown = false;
  if (::isatty(STDERR_FILENO))
    load.meshing.progress = [&](double seconds) {
      std::cerr << "\rmtcut: meshing " << spec << " with TetGen: " << static_cast<long>(seconds) << " s" << std::flush;
      shown = true;
    };
  const auto erase = [&] {
    if (shown) std::cerr << "\r\033[K" << std::flush;
  };
  engine::LoadedMesh loaded;
  try {
    loaded = engine::load_mesh(spec, load);
  } catch (...) {
    erase();
    throw;
  }
  erase();
  for (const engine::InputNote& note : loaded.notes) std::cerr << "mtcut: " << add_advice(note.text, note.hint) << "\n";
  return loaded;
}

}  // namespace mtcut::app
