#include "engine/mesh_loader.h"

#include <filesystem>

#include "engine/input_error.h"
#include "engine/io/mesh_file.h"
#include "engine/surface_mesh.h"

namespace mtcut::engine {

LoadedMesh load_mesh(const std::string& spec, const MeshLoadDef& def) {
  if (const auto shape = parse_builtin(spec)) {
    BuiltinShapeDef shape_def;
    shape_def.shape = *shape;
    shape_def.size = def.builtin_size;
    shape_def.target_tets = def.builtin_tets;
    return {make_builtin_mesh(shape_def, def.meshing), "builtin"};
  }
  if (is_surface_file(spec)) return {tetrahedralize(read_surface_file(spec), def.meshing, spec), "surface"};
  if (!is_volume_file(spec))
    throw InputError(spec + ": unknown mesh format (surfaces: .obj .off .stl .ply; tet meshes: .node .ele .msh .vtk .vtu)");

  RawMesh raw = read_volume_file(spec);
  if (!raw.tets.empty()) return {make_tet_mesh(std::move(raw.positions), raw.tets, spec), "volume"};
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
  return {tetrahedralize(surface, def.meshing, spec), "surface"};
}

}  // namespace mtcut::engine
