#pragma once
// A triangle surface: the input of the mesher and the boundary of a tet mesh
// on output. Surface files (OBJ, OFF, STL, PLY) are read and written through
// OpenMesh; polygon faces are triangulated on reading.

#include <array>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "engine/io/mesh_file.h"
#include "engine/predicates.h"

namespace mtcut::engine {

struct TetMesh;

struct SurfaceMesh {
  std::vector<Vec3> positions;                       // (n_vertices)
  std::vector<std::array<std::int32_t, 3>> triangles;  // (n_triangles) vertex ids, outward for a closed surface

  // Volume enclosed (divergence theorem); positive for an outward-oriented closed surface.
  double enclosed_volume() const;
  // Edges used by other than exactly two triangles: holes or non-manifold seams.
  std::size_t count_open_edges() const;
};

// True for the extensions read_surface_file handles (.obj .off .stl .ply).
bool is_surface_file(const std::string& path);

// Reads a surface with OpenMesh, triangulating polygons; drops unused
// vertices. `format` (OBJ, OFF, STL or PLY) overrides the extension's.
// Throws InputError for a missing, empty or unreadable file, or non-finite coordinates.
SurfaceMesh read_surface_file(const std::string& path, MeshFormat format = MeshFormat::kUnknown);

// Writes a surface (format from the extension: .obj .off .stl .ply) through
// OpenMesh, atomically, every face: one that would make an edge or a vertex
// non-manifold goes over copies of its vertices. Throws InputError when the
// path cannot be written, std::invalid_argument for a face whose vertex ids
// repeat or are out of range.
void write_surface_file(const SurfaceMesh& surface, const std::string& path);

// A surface in a child process's result (engine/child_process.h): written
// by the child, read back by the parent at `at`, which moves on. get_surface
// is false for a result too short for the counts it gives.
bool put_surface(std::FILE* result, const SurfaceMesh& surface);
bool get_surface(const std::string& result, std::size_t& at, SurfaceMesh& surface);

// The boundary of a tet mesh as a surface over the same vertex ids compacted.
SurfaceMesh extract_boundary(const TetMesh& mesh);

}  // namespace mtcut::engine
