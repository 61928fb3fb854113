#pragma once
// One entry point from "what the user named" to a TetMesh: a builtin shape,
// a surface file to mesh, or a tet mesh file to read. Used by every command.

#include <string>

#include "engine/builtin_shapes.h"
#include "engine/tet_mesh.h"
#include "engine/tetrahedralize.h"

namespace mtcut::engine {

struct MeshLoadDef {
  TetrahedralizeOptions meshing;  // for builtin shapes and surfaces
  Vec3 builtin_size = BuiltinShapeDef{}.size;
  int builtin_tets = BuiltinShapeDef{}.target_tets;
};

// What happened on the way, for the report.
struct LoadedMesh {
  TetMesh mesh;
  std::string kind;  // "builtin", "surface" or "volume"
};

// `spec` is builtin:NAME, a surface (.obj .off .stl .ply, or a .vtk/.msh
// holding only triangles) or a tet mesh file. Throws InputError.
LoadedMesh load_mesh(const std::string& spec, const MeshLoadDef& def);

}  // namespace mtcut::engine
