#include "app/mesh_command.h"

#include <chrono>
#include <iostream>

#include "app/cli_checks.h"
#include "app/json_report.h"
#include "app/mesh_input_options.h"
#include "engine/input_error.h"
#include "engine/io/mesh_file.h"
#include "engine/mesh_loader.h"
#include "engine/stopwatch.h"
#include "engine/surface_mesh.h"
#include "engine/text.h"

namespace mtcut::app {
namespace {

struct MeshOptions {
  std::string input;
  std::string output;
  engine::MeshLoadDef load;
  MeshInputOptions mesh_input;
  bool json = false;
};

void run_mesh(MeshOptions& options) {
  apply_mesh_input_options(options.mesh_input, options.load);
  const auto start = std::chrono::steady_clock::now();
  const engine::LoadedMesh loaded = load_input_mesh(options.input, options.load);
  const double seconds = engine::seconds_since(start);
  if (!options.output.empty()) write_mesh_output(loaded.mesh, options.output);

  nlohmann::ordered_json out = {{"input", options.input}, {"source", loaded.kind}};
  out.update(to_json(engine::compute_stats(loaded.mesh)));
  out["seconds"] = seconds;
  if (!options.output.empty()) out["output"] = options.output;
  print_report(std::cout, out, options.json);
}

}  // namespace

void write_mesh_output(const engine::TetMesh& mesh, const std::string& path) {
  const std::string ext = engine::lower_extension(path);
  if (ext == ".vtu") {
    engine::write_vtu(mesh, path,
                      {{"min_dihedral_deg", engine::tet_min_dihedral_deg(mesh)},
                       {"radius_ratio", engine::tet_radius_ratio(mesh)}});
  } else if (ext == ".node" || ext == ".ele") {
    engine::write_tetgen(mesh, path);
  } else if (engine::is_surface_file(path)) {
    engine::write_surface_file(engine::extract_boundary(mesh), path);
  } else {
    throw engine::InputError(path + ": unknown output format (use .vtu, .node, .ele, .obj, .off, .stl or .ply)");
  }
}

void register_mesh_command(CLI::App& app) {
  auto options = std::make_shared<MeshOptions>();
  CLI::App* cmd = app.add_subcommand(
      "mesh",
      "Mesh a surface or a builtin shape with TetGen, or read a tet mesh; validate it, write it, print statistics.\n"
      "  mtcut mesh ../shared/meshes/liver2.obj --json\n"
      "  mtcut mesh builtin:box --tets 100000 -o box.vtu");
  cmd->add_option("input", options->input,
                  "builtin:box | builtin:ellipsoid | builtin:cylinder, a surface (.obj .off .stl .ply) "
                  "or a tet mesh (.node .ele .msh .vtk .vtu)")
      ->required();
  cmd->add_option("-o,--output", options->output,
                  "write the mesh: .vtu (with quality), .node/.ele, or its boundary as .obj/.off/.stl/.ply");
  cmd->add_option("--quality", options->load.meshing.radius_edge_ratio,
                  "TetGen radius-edge ratio bound when meshing (0 = no quality refinement)")
      ->capture_default_str()
      ->check(non_negative_number());
  cmd->add_option("--min-dihedral", options->load.meshing.min_dihedral_deg, "dihedral angle (degrees) TetGen aims for")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 30.0));
  add_mesh_input_options(*cmd, options->load, options->mesh_input);
  cmd->add_flag("--json", options->json, "print the statistics as one JSON object");
  cmd->add_flag("--verbose", options->load.meshing.verbose, "show TetGen's own output");
  cmd->callback([options] { run_mesh(*options); });
}

}  // namespace mtcut::app
