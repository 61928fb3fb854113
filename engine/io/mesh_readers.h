#pragma once
// The readers behind read_volume_file, one per format, for mesh_file.cpp
// and the tests. Each reads the whole file and checks its own syntax and
// counts; faults are InputError naming the file and the line or element.

#include <string>
#include <utility>

#include "engine/io/mesh_file.h"

namespace mtcut::engine {

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
