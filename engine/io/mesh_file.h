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

// True for .node, .ele, .msh, .vtk, .vtu (case-insensitive).
bool is_volume_file(const std::string& path);

// Reads any of the formats above by extension. A .node or .ele path reads
// the .node/.ele pair with the same base name.
RawMesh read_volume_file(const std::string& path);

// One scalar per tet, written as VTK cell data.
struct CellField {
  std::string name;
  std::vector<double> values;  // (n_tets)
};

// VTK XML unstructured grid (appended raw binary, readable by ParaView), atomically.
void write_vtu(const TetMesh& mesh, const std::string& path, const std::vector<CellField>& cell_data = {});

// TetGen .node and .ele beside each other (path may end in .node, .ele or
// have no extension), each written atomically.
void write_tetgen(const TetMesh& mesh, const std::string& path);

}  // namespace mtcut::engine
