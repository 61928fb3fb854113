#pragma once
// One entry point from "what the user named" to a TetMesh: a builtin shape,
// a surface file to mesh, or a tet mesh file to read. Used by every command.
// A file's coordinates are in its own length unit (MeshLoadDef::metres_per_unit);
// the mesh returned is in metres, as everything in mtcut is.

#include <optional>
#include <string>
#include <vector>

#include "engine/builtin_shapes.h"
#include "engine/input_error.h"
#include "engine/tet_mesh.h"
#include "engine/tetrahedralize.h"

namespace mtcut::engine {

struct MeshLoadDef {
  TetrahedralizeOptions meshing;  // for builtin shapes and surfaces, in metres
  Vec3 builtin_size = BuiltinShapeDef{}.size;
  int builtin_tets = BuiltinShapeDef{}.target_tets;
  // A mesh file's length unit in metres, as the user states it: its
  // coordinates are multiplied by it as they are read. Builtin shapes are
  // sized in metres and take no unit.
  double metres_per_unit = 1.0;
  bool unit_stated = false;  // the user named the unit (no size warning then)
  // A surface that is not closed, manifold and free of self-intersections
  // is refused, not repaired (surface_repair.h).
  bool strict = false;
};

// What happened on the way, for the report.
struct LoadedMesh {
  TetMesh mesh;
  std::string kind;              // "builtin", "surface" or "volume"
  std::vector<InputNote> notes;  // one line each, for the user: a repair, a size that looks like other units, ...
};

// The metres in one "m", "dm", "cm" or "mm"; nullopt for any other name.
std::optional<double> metres_per_unit(const std::string& name);

// Organ-sized bodies, by their bounding box's diagonal in metres: a size
// outside this range suggests coordinates in other units.
inline constexpr double kPlausibleMinDiagonal = 1e-3;
inline constexpr double kPlausibleMaxDiagonal = 5.0;

// A note when `positions` (metres) are not organ-sized: how large they are,
// read in the unit given, and the unit that would make them so (named, and
// its symbol in a kUnits hint; the hint's unit is empty when no unit does);
// nullopt when they are organ-sized or the unit was stated.
std::optional<InputNote> implausible_size_note(const std::vector<Vec3>& positions, const MeshLoadDef& def,
                                               const std::string& source);

// `spec` is builtin:NAME, a surface (.obj .off .stl .ply, or a .vtk/.msh
// holding only triangles; repaired unless def.strict) or a tet mesh file
// (its pinched vertices split). The mesh is valid (TetMesh::validate).
// Throws InputError naming `spec` and the first fault.
LoadedMesh load_mesh(const std::string& spec, const MeshLoadDef& def);

}  // namespace mtcut::engine
