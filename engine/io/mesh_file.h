#pragma once
// Tetrahedral mesh files: readers for TetGen .node/.ele, Gmsh .msh (1, 2, 4
// ascii), VTK legacy .vtk (ascii and binary; UNSTRUCTURED_GRID and POLYDATA)
// and VTK XML .vtu (ascii, binary inline, appended raw or base64), and writers
// for .vtu and .node/.ele. Readers return raw arrays (RawMesh); the loader
// turns tets into a TetMesh, or triangles (a surface) into a meshing job.
// Every fault is an InputError naming the file and the line or element.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/tet_mesh.h"

namespace mtcut::engine {

// What a mesh file holds, before any checking beyond the file's own syntax.
struct RawMesh {
  std::vector<Vec3> positions;                          // (n_points)
  std::vector<std::array<std::int64_t, 4>> tets;        // (n_tets) 0-based point ids
  std::vector<std::array<std::int64_t, 3>> triangles;   // (n_triangles) 0-based, surface files
};

// The mesh file formats mtcut reads: tet meshes (TetGen, Gmsh, VTK legacy
// and XML; the VTK and Gmsh readers also take surfaces) and surfaces.
enum class MeshFormat { kUnknown, kTetgen, kGmsh, kVtkLegacy, kVtkXml, kObj, kOff, kStl, kPly };

// By the lower-cased extension: .node .ele .msh .vtk .vtu .obj .off .stl .ply.
MeshFormat format_of_extension(const std::string& path);
// By the file's first bytes (a VTK or XML header, $MeshFormat, ply, OFF, an
// STL's "solid" or binary size, OBJ's records); kUnknown when they do not
// tell (TetGen's numbers, an empty or missing file).
MeshFormat format_of_content(const std::string& path);
// What the file is: its content's format where that is known, else its extension's.
MeshFormat format_of_file(const std::string& path);
// "VTK XML", "Gmsh", ...
std::string format_name(MeshFormat format);
// True for the surface-only formats (OBJ, OFF, STL, PLY).
bool is_surface_format(MeshFormat format);

// An STL file is binary: its size is a binary STL's for the triangle count
// its header gives (an 80-byte header, which some exporters begin with the
// ascii keyword "solid", a count, 50 bytes per triangle), or it does not
// begin with "solid" (a damaged binary file, refused for its count).
bool stl_is_binary(const std::string& path);

// True for .node, .ele, .msh, .vtk, .vtu (case-insensitive).
bool is_volume_file(const std::string& path);

// Reads a tet-mesh file in `format` (kTetgen, kGmsh, kVtkLegacy or kVtkXml;
// by default its extension's). A TetGen path reads the .node/.ele pair with
// the same base name.
RawMesh read_volume_file(const std::string& path, MeshFormat format = MeshFormat::kUnknown);

struct SurfaceMesh;  // engine/surface_mesh.h (which includes this header)

// One scalar per cell (tet or triangle), written as VTK cell data.
struct CellField {
  std::string name;
  std::vector<double> values;  // (n_cells)
};

// VTK XML unstructured grid (appended raw binary, readable by ParaView), atomically.
void write_vtu(const TetMesh& mesh, const std::string& path, const std::vector<CellField>& cell_data = {});
// The same with the surface's triangles as its cells.
void write_vtu(const SurfaceMesh& mesh, const std::string& path, const std::vector<CellField>& cell_data = {});

// TetGen .node and .ele beside each other (path may end in .node, .ele or
// have no extension), each written atomically.
void write_tetgen(const TetMesh& mesh, const std::string& path);

}  // namespace mtcut::engine
