#pragma once
// The readers behind read_volume_file, one per format, for mesh_file.cpp
// and the tests. Each reads the whole file and checks its own syntax and
// counts; faults are InputError naming the file and the line or element.

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>

#include "engine/io/mesh_file.h"

namespace mtcut::engine {

// An element type the readers keep: how many points an element of that type
// lists, and how many of them (the first ones) are its corners: 4 for a tet,
// 3 for a triangle. Quadratic elements keep their corners. {0, 0} for the
// types that are skipped (points, lines, quads, hexahedra, ...).
struct CellShape {
  std::size_t points = 0;
  std::size_t corners = 0;
};

// VTK: 10 tet, 24 quadratic tet, 5 triangle, 22 quadratic triangle.
inline CellShape vtk_cell_shape(std::int64_t type) {
  switch (type) {
    case 10: return {4, 4};
    case 24: return {10, 4};
    case 5: return {3, 3};
    case 22: return {6, 3};
    default: return {};
  }
}

// Gmsh: 4 tet, 11 10-node tet, 2 triangle, 9 6-node triangle.
inline CellShape gmsh_cell_shape(std::int64_t type) {
  switch (type) {
    case 4: return {4, 4};
    case 11: return {10, 4};
    case 2: return {3, 3};
    case 9: return {6, 3};
    default: return {};
  }
}

// The .node and .ele paths a path names (either file, or their base name).
std::pair<std::string, std::string> tetgen_pair(const std::string& path);
// TetGen .node (points) and .ele (tets) pair.
RawMesh read_tetgen(const std::string& node_path, const std::string& ele_path);

// Gmsh .msh, ascii: format 1 ($NOD/$ELM), 2.x and 4.0/4.1.
RawMesh read_gmsh(const std::string& path);

// Legacy VTK .vtk, ascii or binary: UNSTRUCTURED_GRID or POLYDATA.
RawMesh read_vtk_legacy(const std::string& path);

// VTK XML .vtu: ascii, inline base64 binary, appended raw or base64.
RawMesh read_vtu(const std::string& path);

}  // namespace mtcut::engine
