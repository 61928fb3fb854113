// Which format a mesh file is in (by extension and by content), and which
// reader reads each. The readers themselves live one per format.

#include "engine/io/mesh_file.h"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "engine/input_error.h"
#include "engine/io/mesh_readers.h"
#include "engine/text.h"

namespace mtcut::engine {
namespace {

bool starts_with(const std::string& text, const char* prefix) { return text.rfind(prefix, 0) == 0; }

// A binary STL: an 80-byte header, a triangle count, 50 bytes per triangle.
bool is_binary_stl(const std::string& path, const std::string& head) {
  if (head.size() < 84) return false;
  std::uint32_t triangles = 0;
  std::memcpy(&triangles, head.data() + 80, sizeof triangles);
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  return !ec && triangles > 0 && size == 84 + 50 * static_cast<std::uintmax_t>(triangles);
}

// The first token of the first line that is not blank or a comment.
std::string first_record(const std::string& head) {
  std::istringstream lines(head);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream tokens(line);
    std::string token;
    if (!(tokens >> token) || token[0] == '#') continue;
    return token;
  }
  return {};
}

}  // namespace

MeshFormat format_of_extension(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".node" || ext == ".ele") return MeshFormat::kTetgen;
  if (ext == ".msh") return MeshFormat::kGmsh;
  if (ext == ".vtk") return MeshFormat::kVtkLegacy;
  if (ext == ".vtu") return MeshFormat::kVtkXml;
  if (ext == ".obj") return MeshFormat::kObj;
  if (ext == ".off") return MeshFormat::kOff;
  if (ext == ".stl") return MeshFormat::kStl;
  if (ext == ".ply") return MeshFormat::kPly;
  return MeshFormat::kUnknown;
}

MeshFormat format_of_content(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(1024, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  if (head.empty()) return MeshFormat::kUnknown;
  if (is_binary_stl(path, head)) return MeshFormat::kStl;
  std::size_t start = 0;
  if (starts_with(head, "\xEF\xBB\xBF")) start = 3;  // a UTF-8 byte-order mark
  while (start < head.size() && is_space(head[start])) ++start;
  const std::string text = head.substr(start);
  if (starts_with(text, "<?xml") || starts_with(text, "<VTKFile")) return MeshFormat::kVtkXml;
  if (starts_with(text, "# vtk DataFile")) return MeshFormat::kVtkLegacy;
  if (starts_with(text, "$MeshFormat") || starts_with(text, "$NOD") || starts_with(text, "$Comments"))
    return MeshFormat::kGmsh;
  if (starts_with(text, "ply\n") || starts_with(text, "ply\r\n")) return MeshFormat::kPly;
  if (starts_with(text, "solid")) return MeshFormat::kStl;
  const std::string record = first_record(text);
  if (record.size() >= 3 && record.compare(record.size() - 3, 3, "OFF") == 0) return MeshFormat::kOff;
  for (const char* obj : {"v", "vn", "vt", "f", "o", "g", "s", "usemtl", "mtllib"})
    if (record == obj) return MeshFormat::kObj;
  return MeshFormat::kUnknown;
}

MeshFormat format_of_file(const std::string& path) {
  const MeshFormat content = format_of_content(path);
  return content != MeshFormat::kUnknown ? content : format_of_extension(path);
}

std::string format_name(MeshFormat format) {
  switch (format) {
    case MeshFormat::kTetgen: return "TetGen";
    case MeshFormat::kGmsh: return "Gmsh";
    case MeshFormat::kVtkLegacy: return "legacy VTK";
    case MeshFormat::kVtkXml: return "VTK XML";
    case MeshFormat::kObj: return "OBJ";
    case MeshFormat::kOff: return "OFF";
    case MeshFormat::kStl: return "STL";
    case MeshFormat::kPly: return "PLY";
    case MeshFormat::kUnknown: break;
  }
  return "unknown";
}

bool stl_is_binary(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(84, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return is_binary_stl(path, head) || !starts_with(head, "solid");
}

bool is_surface_format(MeshFormat format) {
  return format == MeshFormat::kObj || format == MeshFormat::kOff || format == MeshFormat::kStl ||
         format == MeshFormat::kPly;
}

bool is_volume_file(const std::string& path) {
  const MeshFormat format = format_of_extension(path);
  return format != MeshFormat::kUnknown && !is_surface_format(format);
}

RawMesh read_volume_file(const std::string& path, MeshFormat format) {
  if (format == MeshFormat::kUnknown) format = format_of_extension(path);
  switch (format) {
    case MeshFormat::kTetgen: {
      const auto [node_path, ele_path] = tetgen_pair(path);
      return read_tetgen(node_path, ele_path);
    }
    case MeshFormat::kGmsh: return read_gmsh(path);
    case MeshFormat::kVtkLegacy: return read_vtk_legacy(path);
    case MeshFormat::kVtkXml: return read_vtu(path);
    default: break;
  }
  throw InputError(path + ": unknown tet-mesh format '" + lower_extension(path) +
                   "' (expected .node, .ele, .msh, .vtk or .vtu)");
}

}  // namespace mtcut::engine
