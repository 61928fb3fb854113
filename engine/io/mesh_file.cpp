// Which files are tet-mesh files, and which reader reads each: by the
// lower-cased extension. The readers themselves live one per format.

#include "engine/io/mesh_file.h"

#include <cctype>
#include <filesystem>

#include "engine/input_error.h"
#include "engine/io/mesh_readers.h"

namespace mtcut::engine {
namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace

bool is_volume_file(const std::string& path) {
  const std::string ext = lower_extension(path);
  return ext == ".node" || ext == ".ele" || ext == ".msh" || ext == ".vtk" || ext == ".vtu";
}

RawMesh read_volume_file(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".node" || ext == ".ele") {
    const auto [node_path, ele_path] = tetgen_pair(path);
    return read_tetgen(node_path, ele_path);
  }
  if (ext == ".msh") return read_gmsh(path);
  if (ext == ".vtk") return read_vtk_legacy(path);
  if (ext == ".vtu") return read_vtu(path);
  throw InputError(path + ": unknown tet-mesh format '" + ext + "' (expected .node, .ele, .msh, .vtk or .vtu)");
}

}  // namespace mtcut::engine
