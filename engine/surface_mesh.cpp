#include "engine/surface_mesh.h"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/IO/importer/ImporterT.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <limits>
#include <map>
#include <set>
#include <unordered_map>

#include "engine/atomic_file.h"
#include "engine/child_process.h"
#include "engine/input_error.h"
#include "engine/tet_adjacency.h"
#include "engine/text.h"

namespace mtcut::engine {
namespace {

struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using OmMesh = OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits>;

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

// OpenMesh's PLY, OFF and binary STL readers loop over the counts a header
// declares, for minutes when a damaged header declares billions: refuse
// counts the file is too short to hold (at least 2 bytes a number in text,
// the exact record sizes in binary).
void reject_impossible_counts(const std::string& path, const std::string& ext) {
  std::error_code ec;
  const auto size = static_cast<double>(std::filesystem::file_size(path, ec));
  std::ifstream in(path, std::ios::binary);
  const auto refuse = [&](const std::string& what) {
    throw InputError(path + ": " + what + ", more than the file's " + std::to_string(static_cast<long long>(size)) +
                     " bytes can hold");
  };
  if (ext == ".ply") {
    // A damaged PLY header also sends OpenMesh's reader into a loop: the
    // header must be one OpenMesh reads as written.
    static const std::set<std::string> kTypes = {"char",  "uchar",  "short",  "ushort", "int",     "uint",
                                                 "float", "double", "int8",   "uint8",  "int16",   "uint16",
                                                 "int32", "uint32", "float32", "float64"};
    const auto bad_header = [&](int line_number) {
      throw InputError(describe_at(path, static_cast<std::size_t>(line_number), "not a PLY header line"));
    };
    std::string line, format;
    double needed = 0;
    bool ended = false;
    for (int n = 1; n <= 500 && std::getline(in, line); ++n) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      std::istringstream words(line);
      std::string key, a, b, c, d;
      words >> key;
      if (n == 1) {
        if (key != "ply" || words >> a) bad_header(n);
        continue;
      }
      if (key == "end_header") {
        ended = true;
        break;
      }
      if (key == "comment" || key == "obj_info") continue;
      if (key == "format") {
        if (!(words >> format >> a) || (format != "ascii" && format != "binary_little_endian" &&
                                        format != "binary_big_endian"))
          bad_header(n);
      } else if (key == "element") {
        if (!(words >> a >> b) || b.empty() || b.find_first_not_of("0123456789") != std::string::npos || b.size() > 12)
          bad_header(n);
        needed += std::stod(b) * (a == "vertex" ? (format == "ascii" ? 6 : 12) : (format == "ascii" ? 2 : 1));
      } else if (key == "property") {
        // "property TYPE NAME" or "property list COUNT_TYPE ITEM_TYPE NAME".
        if (!(words >> a >> b)) bad_header(n);
        if (a == "list" ? !(words >> c >> d) || !kTypes.count(b) || !kTypes.count(c) : !kTypes.count(a)) bad_header(n);
        std::string more;
        if (words >> more) bad_header(n);
      } else {
        bad_header(n);
      }
    }
    if (!ended) throw InputError(path + ": the PLY header has no end_header line");
    if (needed > size) refuse("its header declares " + std::to_string(static_cast<long long>(needed)) + " bytes of elements");
  } else if (ext == ".off") {
    std::string header;
    double vertices = 0, faces = 0;
    if (in >> header && header.size() >= 3 && header.compare(header.size() - 3, 3, "OFF") == 0 &&
        in >> vertices >> faces && vertices * 6 + faces * 8 > size)
      refuse("its header declares " + std::to_string(static_cast<long long>(vertices)) + " vertices and " +
             std::to_string(static_cast<long long>(faces)) + " faces");
  } else if (ext == ".stl") {
    std::string head(84, '\0');
    in.read(head.data(), 84);
    if (in.gcount() == 84 && stl_is_binary(path)) {
      std::uint32_t triangles = 0;
      std::memcpy(&triangles, head.data() + 80, sizeof triangles);
      if (84 + 50.0 * triangles > size) refuse("its header declares " + std::to_string(triangles) + " triangles");
    }
  }
}

// OpenMesh's ascii readers parse numbers with stream extraction, which stops
// at "nan" or "inf" and silently drops or shifts vertices. Scan ascii files
// first and name the line of any non-finite number. Binary files need no
// scan: their NaNs arrive as values and are caught after reading.
//
// Its OBJ reader also skips a record it does not know and keeps going: a
// damaged vertex line ("v*-0.8 ...", "v 0.1 0.2", "v 1e39 0 0": it reads
// floats) is dropped and every face after it then points at the wrong
// vertices. An OBJ's vertex records must hold three decimal numbers in a
// float's range, and its faces' corners vertices it has; a byte order mark
// would hide the first record.
void reject_non_finite_text(const std::string& path, const std::string& ext) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::getline(in, line);
  const bool ascii = ext == ".obj" || ext == ".off" || (ext == ".stl" && !stl_is_binary(path)) ||
                     (ext == ".ply" && [&] {
                       std::string header;
                       while (std::getline(in, header) && header.rfind("format", 0) != 0) {
                       }
                       return header.find("ascii") != std::string::npos;
                     }());
  if (!ascii) return;
  in.clear();
  in.seekg(0);
  const bool obj = ext == ".obj";
  bool in_header = ext == ".ply";  // a PLY header holds words, not numbers
  std::size_t number = 0;
  long long vertices = 0, last_corner = 0;
  std::size_t last_corner_line = 0;
  while (std::getline(in, line)) {
    ++number;
    if (number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0)
      throw InputError(describe_at(path, number, "the file starts with a byte order mark, which the reader would "
                                                 "take for data; save it without one"));
    if (in_header) {
      in_header = line.rfind("end_header", 0) != 0;
      continue;
    }
    std::istringstream tokens(line);
    std::string record;
    if (!(tokens >> record) || record[0] == '#') continue;
    // An OBJ's data records; its other records (g, o, s, usemtl, ...) hold names.
    if (obj && record != "v" && record != "vt" && record != "vn" && record != "vp" && record != "vc" &&
        record != "f") {
      if (record[0] == 'v') throw InputError(describe_at(path, number, "'" + record + "' is not an OBJ record"));
      continue;
    }
    int numbers = 0;
    // In OFF, PLY and STL the first word is data too.
    std::string token = record;
    for (bool first = true; first || tokens >> token; first = false) {
      if (token[0] == '#') break;  // a comment to the line's end
      if (obj && first) continue;
      char* end = nullptr;
      const double value = std::strtod(token.c_str(), &end);
      // The readers take decimal floats: not hexadecimal ones, nor any beyond a float's range.
      const bool is_number = end != token.c_str() && *end == '\0' && token.find_first_of("xX") == std::string::npos;
      if (is_number && !std::isfinite(value))
        throw InputError(describe_at(path, number, "non-finite coordinate '" + token + "'"));
      if (is_number && std::abs(value) > std::numeric_limits<float>::max())
        throw InputError(describe_at(path, number, "coordinate '" + token + "' is beyond a float's range"));
      if (obj && record == "v" && numbers < 3 && !is_number)
        throw InputError(describe_at(path, number, "vertex coordinate '" + token + "' is not a number"));
      if (obj && record == "f") {
        // "i", "i/t", "i//n" or "i/t/n": i counts from 1, or back from the last vertex when negative.
        const long long corner = std::strtoll(token.c_str(), &end, 10);
        if (end == token.c_str() || (*end != '\0' && *end != '/') || corner == 0 || corner < -vertices)
          throw InputError(describe_at(path, number, "face corner '" + token + "' is not a vertex of the file"));
        if (corner > last_corner) last_corner = corner, last_corner_line = number;
      }
      numbers += is_number;
    }
    if (obj && record == "v") {
      if (numbers < 3) throw InputError(describe_at(path, number, "a vertex with fewer than three coordinates"));
      ++vertices;
    }
  }
  if (last_corner > vertices)
    throw InputError(describe_at(path, last_corner_line, "a face corner is vertex " + std::to_string(last_corner) +
                                                             " of a file of " + std::to_string(vertices)));
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

namespace {

// OpenMesh's importer adds each face it reads to a halfedge mesh, which
// refuses a face that would make it non-manifold (two parts that touch
// along an edge or at a vertex); the importer then adds that face over
// copies of its corners. The surface read keeps every face over the file's
// own vertices, as the file gives them: the repair (surface_repair.h) sees
// where the parts touch, and the faces and points it reports are the file's.
class FileFaces : public OpenMesh::IO::ImporterT<OmMesh> {
 public:
  explicit FileFaces(OmMesh& mesh) : ImporterT<OmMesh>(mesh), om_(mesh) {}
  OpenMesh::FaceHandle add_face(const VHandles& corners) override {
    // A damaged file's corner index may name one of the copies (the
    // readers of OFF, PLY and STL take indices as handles): it is not a
    // vertex of the file, and the face is dropped as the importer drops
    // one whose corner is no vertex at all.
    for (const auto& v : corners)
      if (v.is_valid() && static_cast<std::size_t>(v.idx()) < copy_.size() && copy_[static_cast<std::size_t>(v.idx())])
        return OpenMesh::FaceHandle();
    // Invalid when the importer drops the face: fewer than three corners, a
    // corner that is no vertex, or one given twice (no area).
    const std::size_t vertices = om_.n_vertices();
    const OpenMesh::FaceHandle face = ImporterT<OmMesh>::add_face(corners);
    if (om_.n_vertices() > vertices) {
      copy_.resize(om_.n_vertices(), 0);
      std::fill(copy_.begin() + static_cast<std::ptrdiff_t>(vertices), copy_.end(), 1);
    }
    if (face.is_valid()) faces.push_back(corners);
    return face;
  }
  std::vector<VHandles> faces;

 private:
  OmMesh& om_;
  std::vector<std::uint8_t> copy_;  // per vertex up to the last copy the importer made: 1 for a copy
};

// Reads the surface at `read_path` with OpenMesh (in the process it is
// called in); `path` names it in errors.
SurfaceMesh read_with_openmesh(const std::string& path, const std::string& read_path, const std::string& ext) {
  OmMesh om;
  FileFaces file(om);
  {
    QuietOpenMesh quiet;
    OpenMesh::IO::Options options;
    if (!OpenMesh::IO::IOManager().read(read_path, file, options))
      throw InputError(path + ": cannot read it as a surface (" + ext + ")");
  }
  if (file.faces.empty()) throw InputError(path + ": the surface has no faces");

  SurfaceMesh surface;
  std::vector<std::int32_t> remap(om.n_vertices(), -1);
  for (const auto& face : file.faces) {
    std::vector<std::int32_t> loop;
    for (const auto& v : face) {
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

}  // namespace

SurfaceMesh read_surface_file(const std::string& path, MeshFormat format) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path + ": no such file");
  if (std::filesystem::file_size(path, ec) == 0) throw InputError(path + ": the file is empty");

  const std::string ext = format == MeshFormat::kUnknown ? lower_extension(path) : extension_of(format);
  reject_impossible_counts(path, ext);
  reject_non_finite_text(path, ext);
  // OpenMesh's readers abort on some malformed files (an OBJ face of no
  // vertices) and loop on others (a damaged PLY header): they read in a
  // child process, stopped after kReadSeconds.
  constexpr int kReadSeconds = 10;
  // OpenMesh picks its reader by the name's extension: a file whose
  // extension is not its format's is read through a link that has it (made
  // and removed here, whatever becomes of the child).
  const ExtensionLink link(path, ext);
  constexpr int kRead = 0, kRefused = 2;
  ChildOptions read_limit;
  read_limit.deadline = read_limit.start + std::chrono::seconds(kReadSeconds);
  read_limit.keep_chatter = false;
  const ChildRun run = run_in_child(
      [&](std::FILE* result) {
        try {
          return put_surface(result, read_with_openmesh(path, link.path(), ext)) ? kRead : 1;
        } catch (const InputError& e) {
          const std::string what = e.what();
          return put_values(result, what.data(), what.size()) ? kRefused : 1;
        }
      },
      read_limit);
  if (run.outcome == ChildRun::Outcome::kTimedOut)
    throw InputError(path + ": cannot read it as a surface (" + ext + "): the reader did not finish in " +
                     std::to_string(kReadSeconds) + " s");
  if (run.outcome == ChildRun::Outcome::kCrashed)
    throw InputError(path + ": cannot read it as a surface (" + ext + "): the reader crashed (" +
                     signal_name(run.code) + ")");
  if (run.code == kRefused) throw InputError(run.output);
  SurfaceMesh surface;
  std::size_t at = 0;
  if (run.outcome != ChildRun::Outcome::kExited || run.code != kRead || !get_surface(run.output, at, surface))
    throw InputError(path + ": cannot read it as a surface (" + ext + ")");
  return surface;
}

bool put_surface(std::FILE* result, const SurfaceMesh& surface) {
  const std::uint64_t counts[2] = {surface.positions.size(), surface.triangles.size()};
  return put_values(result, counts, 2) && put_values(result, surface.positions.data(), counts[0]) &&
         put_values(result, surface.triangles.data(), counts[1]);
}

bool get_surface(const std::string& result, std::size_t& at, SurfaceMesh& surface) {
  std::uint64_t counts[2] = {0, 0};
  // Counts beyond what the result holds are refused before anything is allocated for them.
  if (!get_values(result, at, counts, 2) || counts[0] > result.size() / sizeof(Vec3) ||
      counts[1] > result.size() / sizeof(surface.triangles[0]))
    return false;
  surface.positions.resize(counts[0]);
  surface.triangles.resize(counts[1]);
  return get_values(result, at, surface.positions.data(), counts[0]) &&
         get_values(result, at, surface.triangles.data(), counts[1]);
}

void write_surface_file(const SurfaceMesh& surface, const std::string& path) {
  if (!is_surface_file(path))
    throw InputError(path + ": unknown surface format (use .obj, .off, .stl or .ply)");
  OmMesh om;
  std::vector<OmMesh::VertexHandle> handles;
  handles.reserve(surface.positions.size());
  for (const auto& p : surface.positions) handles.push_back(om.add_vertex(OmMesh::Point(p.x(), p.y(), p.z())));
  QuietOpenMesh quiet;
  // OpenMesh's halfedge mesh refuses a face that would make it non-manifold
  // (pieces of a cut that touch along an edge) or that is turned against a
  // neighbour: such a face is written over copies of its vertices, shared
  // by the faces refused (or over copies of its own when they clash too),
  // so that no face is lost.
  std::vector<OmMesh::VertexHandle> copy_of(handles.size());
  // (From the surface's positions: a reference to the mesh's own point would
  // not survive the storage it lives in growing.)
  const auto copy_of_point = [&](std::int32_t v) {
    const Vec3& p = surface.positions[v];
    return om.add_vertex(OmMesh::Point(p.x(), p.y(), p.z()));
  };
  const auto copy = [&](std::int32_t v) {
    if (!copy_of[v].is_valid()) copy_of[v] = copy_of_point(v);
    return copy_of[v];
  };
  for (std::size_t f = 0; f < surface.triangles.size(); ++f) {
    const auto& t = surface.triangles[f];
    const auto n = static_cast<std::int64_t>(handles.size());
    if (std::min({t[0], t[1], t[2]}) < 0 || std::max({t[0], t[1], t[2]}) >= n || t[0] == t[1] || t[1] == t[2] ||
        t[0] == t[2])
      throw std::invalid_argument("write_surface_file: face " + std::to_string(f) + " has vertex ids " +
                                  std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) +
                                  " of " + std::to_string(n));
    if (om.add_face(handles[t[0]], handles[t[1]], handles[t[2]]).is_valid()) continue;
    if (om.add_face(copy(t[0]), copy(t[1]), copy(t[2])).is_valid()) continue;
    std::array<OmMesh::VertexHandle, 3> own;
    for (int k = 0; k < 3; ++k) own[k] = copy_of_point(t[k]);
    om.add_face(own[0], own[1], own[2]);
  }
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
