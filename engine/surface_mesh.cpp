#include "engine/surface_mesh.h"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <map>
#include <unordered_map>

#include "engine/atomic_file.h"
#include "engine/input_error.h"
#include "engine/tet_adjacency.h"

namespace mtcut::engine {
namespace {

struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using OmMesh = OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits>;

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// OpenMesh prints its warnings (e.g. skipped complex faces) to omerr/omlog;
// they are not ours to show, so keep them quiet while we use it.
struct QuietOpenMesh {
  QuietOpenMesh() {
    omerr().disable();
    omlog().disable();
    omout().disable();
  }
  ~QuietOpenMesh() {
    omerr().enable();
    omlog().enable();
    omout().enable();
  }
};

// OpenMesh's ascii readers parse numbers with stream extraction, which stops
// at "nan" or "inf" and silently drops or shifts vertices. Scan ascii files
// first and name the line of any non-finite number. Binary files need no
// scan: their NaNs arrive as values and are caught after reading.
void reject_non_finite_text(const std::string& path, const std::string& ext) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::getline(in, line);
  const bool ascii = ext == ".obj" || ext == ".off" || (ext == ".stl" && line.rfind("solid", 0) == 0) ||
                     (ext == ".ply" && [&] {
                       std::string header;
                       while (std::getline(in, header) && header.rfind("format", 0) != 0) {
                       }
                       return header.find("ascii") != std::string::npos;
                     }());
  if (!ascii) return;
  in.clear();
  in.seekg(0);
  std::size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    std::istringstream tokens(line);
    std::string token;
    while (tokens >> token) {
      char* end = nullptr;
      const double value = std::strtod(token.c_str(), &end);
      if (end != token.c_str() && *end == '\0' && !std::isfinite(value))
        throw InputError(describe_at(path, number, "non-finite coordinate '" + token + "'"));
    }
  }
}

std::string extension_of(MeshFormat format) {
  switch (format) {
    case MeshFormat::kObj: return ".obj";
    case MeshFormat::kOff: return ".off";
    case MeshFormat::kStl: return ".stl";
    case MeshFormat::kPly: return ".ply";
    default: throw InputError("read_surface_file: " + format_name(format) + " is not a surface format");
  }
}

// `path` itself when its extension is `ext`, else a symbolic link to it
// named with `ext` in the temp folder, removed with the object.
class ExtensionLink {
 public:
  ExtensionLink(const std::string& path, const std::string& ext) : path_(path) {
    if (lower_extension(path) == ext) return;
    static std::atomic<int> counter{0};
    link_ = std::filesystem::temp_directory_path() /
            ("mtcut-read-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ext);
    std::error_code ec;
    std::filesystem::create_symlink(std::filesystem::absolute(path), link_, ec);
    if (ec) throw InputError(path + ": cannot read it as " + ext + " (" + ec.message() + ")");
  }
  ~ExtensionLink() {
    std::error_code ignored;
    if (!link_.empty()) std::filesystem::remove(link_, ignored);
  }
  ExtensionLink(const ExtensionLink&) = delete;
  ExtensionLink& operator=(const ExtensionLink&) = delete;
  std::string path() const { return link_.empty() ? path_ : link_.string(); }

 private:
  std::string path_;
  std::filesystem::path link_;
};

}  // namespace

double SurfaceMesh::enclosed_volume() const {
  double sum = 0;
  for (const auto& t : triangles)
    sum += positions[t[0]].dot(positions[t[1]].cross(positions[t[2]]));
  return sum / 6.0;
}

std::size_t SurfaceMesh::count_open_edges() const {
  std::map<std::pair<std::int32_t, std::int32_t>, int> uses;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) {
      auto a = t[k], b = t[(k + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  return static_cast<std::size_t>(std::count_if(uses.begin(), uses.end(), [](const auto& e) { return e.second != 2; }));
}

bool is_surface_file(const std::string& path) { return is_surface_format(format_of_extension(path)); }

SurfaceMesh read_surface_file(const std::string& path, MeshFormat format) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path + ": no such file");
  if (std::filesystem::file_size(path, ec) == 0) throw InputError(path + ": the file is empty");

  const std::string ext = format == MeshFormat::kUnknown ? lower_extension(path) : extension_of(format);
  reject_non_finite_text(path, ext);
  OmMesh om;
  {
    QuietOpenMesh quiet;
    OpenMesh::IO::Options options;
    // OpenMesh picks its reader by the name's extension: a file whose
    // extension is not its format's is read through a link that has it.
    const ExtensionLink link(path, ext);
    if (!OpenMesh::IO::read_mesh(om, link.path(), options))
      throw InputError(path + ": cannot read it as a surface (" + ext + ")");
  }
  if (om.n_faces() == 0) throw InputError(path + ": the surface has no faces");

  SurfaceMesh surface;
  std::vector<std::int32_t> remap(om.n_vertices(), -1);
  for (const auto& f : om.faces()) {
    std::vector<std::int32_t> loop;
    for (const auto& v : om.fv_range(f)) {
      auto& id = remap[static_cast<std::size_t>(v.idx())];
      if (id < 0) {
        const auto& p = om.point(v);
        const Vec3 q(p[0], p[1], p[2]);
        if (!q.allFinite())
          throw InputError(path + ": vertex " + std::to_string(v.idx() + 1) + " has a non-finite coordinate");
        id = static_cast<std::int32_t>(surface.positions.size());
        surface.positions.push_back(q);
      }
      loop.push_back(id);
    }
    // Polygons are fanned from their first corner; the faces we read are
    // planar-convex in practice (OBJ quads); TetGen refines them anyway.
    for (std::size_t k = 1; k + 1 < loop.size(); ++k) surface.triangles.push_back({loop[0], loop[k], loop[k + 1]});
  }
  return surface;
}

void write_surface_file(const SurfaceMesh& surface, const std::string& path) {
  if (!is_surface_file(path))
    throw InputError(path + ": unknown surface format (use .obj, .off, .stl or .ply)");
  OmMesh om;
  std::vector<OmMesh::VertexHandle> handles;
  handles.reserve(surface.positions.size());
  for (const auto& p : surface.positions) handles.push_back(om.add_vertex(OmMesh::Point(p.x(), p.y(), p.z())));
  QuietOpenMesh quiet;
  for (const auto& t : surface.triangles) om.add_face(handles[t[0]], handles[t[1]], handles[t[2]]);
  write_atomically(path, [&](const std::string& temp) {
    OpenMesh::IO::Options options;
    return OpenMesh::IO::write_mesh(om, temp, options, 17);
  });
}

SurfaceMesh extract_boundary(const TetMesh& mesh) {
  const TetAdjacency adj = build_adjacency(mesh);
  SurfaceMesh surface;
  std::unordered_map<std::int32_t, std::int32_t> remap;
  for (const auto& bf : adj.boundary) {
    std::array<std::int32_t, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      auto [it, inserted] = remap.emplace(bf.verts[k].value, static_cast<std::int32_t>(surface.positions.size()));
      if (inserted) surface.positions.push_back(mesh.position(bf.verts[k]));
      tri[k] = it->second;
    }
    surface.triangles.push_back(tri);
  }
  return surface;
}

}  // namespace mtcut::engine
