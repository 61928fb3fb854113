#include "app/cut_command.h"

#include <iostream>

#include "app/json_report.h"
#include "app/mesh_command.h"
#include "app/mesh_input_options.h"
#include "cut/cut_polygon.h"
#include "cut/lut/split_table.h"
#include "engine/input_error.h"
#include "engine/mesh_loader.h"

namespace mtcut::app {
namespace {

struct CutOptions {
  std::string input;
  std::string polygon;
  std::string scheme = "lut";
  std::string output;
  engine::MeshLoadDef load;
  MeshInputOptions mesh_input;
  cut::CutterDef cutter;
  bool json = false;
};

void run_cut(CutOptions& options) {
  const auto scheme = cut::parse_scheme(options.scheme);
  if (!scheme) throw engine::InputError("--scheme " + options.scheme + ": unknown scheme (known: lut, bielser17)");
  options.cutter.scheme = *scheme;
  // The polygon first: a typo in it should not wait for the meshing.
  const cut::CutPolygon polygon = cut::parse_cut_polygon(options.polygon, "--polygon");
  apply_mesh_input_options(options.mesh_input, options.load);
  engine::LoadedMesh loaded = load_input_mesh(options.input, options.load);
  const std::size_t tets_before = loaded.mesh.num_tets();
  const std::size_t vertices_before = loaded.mesh.num_vertices();

  const cut::MeshCutResult result = cut::cut_mesh(loaded.mesh, polygon, options.cutter);
  const engine::ValidationReport valid = loaded.mesh.validate();
  if (!valid.ok())
    throw engine::InputError(options.input + ": the cut left an invalid mesh (an internal error; please report it): " +
                             valid.problems.front());
  if (!options.output.empty()) write_mesh_output(loaded.mesh, options.output);

  nlohmann::ordered_json out = {{"input", options.input},
                                {"scheme", cut::scheme_name(options.cutter.scheme)},
                                {"polygon_corners", polygon.size()},
                                {"tets_before", tets_before},
                                {"vertices_before", vertices_before}};
  out.update(cut_stats_json(result.stats));
  out["tets"] = loaded.mesh.num_tets();
  out["vertices"] = loaded.mesh.num_vertices();
  if (!options.output.empty()) out["output"] = options.output;
  print_report(std::cout, out, options.json);
}

}  // namespace

nlohmann::ordered_json cut_stats_json(const cut::CutStats& stats) {
  nlohmann::ordered_json cases = nlohmann::ordered_json::object();
  for (std::size_t c = 0; c < cut::kCaseCount; ++c)
    cases[cut::case_name(static_cast<cut::CutCase>(c))] = stats.per_case[c];
  nlohmann::ordered_json out = {{"split_tets", stats.split_tets},
                                {"new_tets", stats.new_tets},
                                {"new_tets_per_split_tet", stats.new_tets_per_split_tet()},
                                {"cases", cases},
                                {"pieces", stats.pieces},
                                {"min_dihedral_deg", nullptr},
                                {"new_vertices", stats.new_vertices},
                                {"split_vertices", stats.split_vertices},
                                {"snapped_vertices", stats.snapped_vertices},
                                {"seconds", stats.seconds}};
  if (stats.new_tets > 0) out["min_dihedral_deg"] = stats.min_dihedral_deg;
  return out;
}

void register_cut_command(CLI::App& app) {
  auto options = std::make_shared<CutOptions>();
  CLI::App* cmd = app.add_subcommand(
      "cut",
      "Cut a single-resolution tet mesh by one planar convex polygon; write it; print the split tets, the new tets, "
      "the cases, the pieces.\n"
      "  mtcut cut builtin:box --tets 2000 --polygon \"0,-1,-1;0,1,-1;0,1,1;0,-1,1\" --json\n"
      "  mtcut cut ../shared/meshes/liver.msh --polygon \"-1.2,-1,-3;-1.2,7,-3;-1.2,7,4;-1.2,-1,4\" "
      "--scheme bielser17 -o cut.vtu");
  cmd->add_option("input", options->input, "builtin:NAME, a surface to mesh, or a tet mesh file (as for `mtcut mesh`)")
      ->required();
  cmd->add_option("--polygon", options->polygon,
                  "the cut: corners \"x,y,z;x,y,z;...\" (at least 3, in order, planar and convex), in metres (the mesh's coordinates after --units or --scale)")
      ->required();
  cmd->add_option("--scheme", options->scheme, "split scheme: lut (the paper's) or bielser17 (the 1:17 reference)")
      ->capture_default_str();
  cmd->add_option("--snap", options->cutter.snap,
                  "cut points nearer a vertex than this fraction of the edge snap onto it")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 0.45));
  cmd->add_option("-o,--output", options->output,
                  "write the cut mesh: .vtu (with quality), .node/.ele, or its boundary as .obj/.off/.stl/.ply");
  add_mesh_input_options(*cmd, options->load, options->mesh_input);
  cmd->add_flag("--json", options->json, "print one JSON object");
  cmd->callback([options] { run_cut(*options); });
}

}  // namespace mtcut::app
