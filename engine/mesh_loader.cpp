#include "engine/mesh_loader.h"

#include <array>
#include <cmath>
#include <cstdio>

#include "engine/input_error.h"
#include "engine/io/mesh_file.h"
#include "engine/surface_mesh.h"
#include "engine/surface_repair.h"

namespace mtcut::engine {
namespace {

struct NamedUnit {
  const char* symbol;
  const char* name;
  double metres;
};
constexpr std::array<NamedUnit, 4> kUnits = {{{"m", "metres", 1.0},
                                              {"dm", "decimetres", 0.1},
                                              {"cm", "centimetres", 0.01},
                                              {"mm", "millimetres", 0.001}}};

// The size an organ is taken to have when suggesting a unit.
constexpr double kTypicalDiagonal = 0.2;

std::string unit_name(double metres_per_unit) {
  for (const NamedUnit& u : kUnits)
    if (u.metres == metres_per_unit) return u.name;
  char text[64];
  std::snprintf(text, sizeof text, "units of %g m", metres_per_unit);
  return text;
}

std::string format_length(double metres) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3g m", metres);
  return text;
}

void scale_positions(std::vector<Vec3>& positions, double metres_per_unit) {
  if (metres_per_unit == 1.0) return;
  for (Vec3& p : positions) p *= metres_per_unit;
}

TetMesh mesh_surface(SurfaceMesh surface, const MeshLoadDef& def, const std::string& spec,
                     std::vector<InputNote>& notes) {
  scale_positions(surface.positions, def.metres_per_unit);
  if (auto note = implausible_size_note(surface.positions, def, spec)) notes.push_back(std::move(*note));
  if (def.strict) return tetrahedralize(surface, def.meshing, spec, &notes);
  const SurfaceMesh input = surface;
  const SurfaceRepair repair = repair_surface(surface, spec);
  try {
    TetMesh mesh = tetrahedralize(surface, def.meshing, spec, &notes);
    if (repair.changed()) notes.push_back({repair.describe(spec)});
    return mesh;
  } catch (const SurfaceRefused&) {
    // What TetGen still refuses for its geometry (faces closer than its
    // tolerance, a crossing CGAL's check missed) is wrapped whole; a limit
    // it ran into (time, memory) is not retried.
    if (repair.step == SurfaceRepair::Step::kWrap) throw;
    surface = input;
    const SurfaceRepair wrapped = repair_surface(surface, spec, true);
    TetMesh mesh = tetrahedralize(surface, def.meshing, spec, &notes);
    notes.push_back({wrapped.describe(spec) + " (TetGen refused the " +
                     (repair.changed() ? std::string("lighter repair") : std::string("surface as it was")) + ")"});
    return mesh;
  }
}

LoadedMesh load_file(const std::string& spec, const MeshLoadDef& def) {
  LoadedMesh loaded;
  // The content decides where it tells: XML VTK named .vtk, an OBJ named .stl.
  const MeshFormat named = format_of_extension(spec), format = format_of_file(spec);
  if (format == MeshFormat::kUnknown)
    throw InputError(spec + ": unknown mesh format (surfaces: .obj .off .stl .ply; tet meshes: .node .ele .msh .vtk .vtu)");
  if (format != named)
    loaded.notes.push_back({spec + ": read as " + format_name(format) + ", which its content is" +
                            (named == MeshFormat::kUnknown ? std::string() : ", not " + format_name(named))});
  if (is_surface_format(format)) {
    loaded.mesh = mesh_surface(read_surface_file(spec, format), def, spec, loaded.notes);
    loaded.kind = "surface";
    return loaded;
  }

  RawMesh raw = read_volume_file(spec, format);
  if (!raw.tets.empty()) {
    scale_positions(raw.positions, def.metres_per_unit);
    if (auto note = implausible_size_note(raw.positions, def, spec)) loaded.notes.push_back(std::move(*note));
    loaded.mesh = make_tet_mesh(std::move(raw.positions), raw.tets, spec);
    if (const std::size_t split = split_pinched_vertices(loaded.mesh); split > 0)
      loaded.notes.push_back({spec + ": parts of the mesh touch only at " + std::to_string(split) +
                              (split == 1 ? " vertex" : " vertices") +
                              " (or along edges through them); each part has its own copy of those vertices now"});
    loaded.kind = "volume";
    return loaded;
  }
  if (raw.triangles.empty()) throw InputError(spec + ": the file holds no tetrahedra and no triangles");
  // A surface in a volume format (e.g. VTK POLYDATA): mesh its inside.
  SurfaceMesh surface;
  const auto n = static_cast<std::int64_t>(raw.positions.size());
  for (std::size_t t = 0; t < raw.triangles.size(); ++t) {
    std::array<std::int32_t, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      const std::int64_t id = raw.triangles[t][k];
      if (id < 0 || id >= n)
        throw InputError(spec + ": triangle " + std::to_string(t) + " refers to point " + std::to_string(id) +
                         ", but there are " + std::to_string(n) + " points");
      tri[k] = static_cast<std::int32_t>(id);
    }
    surface.triangles.push_back(tri);
  }
  surface.positions = std::move(raw.positions);
  for (std::size_t v = 0; v < surface.positions.size(); ++v)
    if (!surface.positions[v].allFinite())
      throw InputError(spec + ": point " + std::to_string(v) + " has a non-finite coordinate");
  loaded.mesh = mesh_surface(std::move(surface), def, spec, loaded.notes);
  loaded.kind = "surface";
  return loaded;
}

}  // namespace

std::optional<double> metres_per_unit(const std::string& name) {
  for (const NamedUnit& u : kUnits)
    if (name == u.symbol) return u.metres;
  return std::nullopt;
}

std::optional<InputNote> implausible_size_note(const std::vector<Vec3>& positions, const MeshLoadDef& def,
                                               const std::string& source) {
  if (def.unit_stated || positions.empty()) return std::nullopt;
  Vec3 lo = positions.front(), hi = lo;
  for (const Vec3& p : positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double diagonal = (hi - lo).norm();
  if (!(diagonal > 0) || (diagonal >= kPlausibleMinDiagonal && diagonal <= kPlausibleMaxDiagonal))
    return std::nullopt;
  // The unit that brings the body nearest an organ's size.
  const double in_file_units = diagonal / def.metres_per_unit;
  const NamedUnit* best = &kUnits.front();
  for (const NamedUnit& u : kUnits)
    if (std::abs(std::log(in_file_units * u.metres / kTypicalDiagonal)) <
        std::abs(std::log(in_file_units * best->metres / kTypicalDiagonal)))
      best = &u;
  InputNote note{source + ": the mesh is " + format_length(diagonal) +
                     " across (its bounding box's diagonal) with its coordinates read as " +
                     unit_name(def.metres_per_unit) + ", which is not an organ's size",
                 {InputHint::Kind::kUnits, {}}};
  if (best->metres != def.metres_per_unit && in_file_units * best->metres >= kPlausibleMinDiagonal &&
      in_file_units * best->metres <= kPlausibleMaxDiagonal) {
    note.text += std::string("; they may be ") + best->name;
    note.hint.unit = best->symbol;
  }
  return note;
}

LoadedMesh load_mesh(const std::string& spec, const MeshLoadDef& def) {
  if (!(def.metres_per_unit > 0) || !std::isfinite(def.metres_per_unit))
    throw InputError(spec + ": the mesh's unit must be a positive length in metres");
  LoadedMesh loaded;
  if (const auto shape = parse_builtin(spec)) {
    if (def.metres_per_unit != 1.0)
      throw InputError(spec + ": a builtin shape is sized in metres; a unit applies to mesh files only");
    BuiltinShapeDef shape_def;
    shape_def.shape = *shape;
    shape_def.size = def.builtin_size;
    shape_def.target_tets = def.builtin_tets;
    loaded = {make_builtin_mesh(shape_def, def.meshing), "builtin", {}};
  } else {
    loaded = load_file(spec, def);
  }
  if (const ValidationReport report = loaded.mesh.validate(); !report.ok())
    throw InputError(spec + ": invalid tet mesh: " + report.problems.front());
  return loaded;
}

}  // namespace mtcut::engine
