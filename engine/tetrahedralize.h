#pragma once
// Volume meshing of a closed triangle surface through the TetGen library
// (a PLC in, a constrained quality Delaunay mesh out). TetGen reports faults
// by printing to stdout and throwing an int; this wrapper captures both and
// turns them into one InputError line (self-intersections name the faces).

#include <string>

#include "engine/surface_mesh.h"
#include "engine/tet_mesh.h"

namespace mtcut::engine {

struct TetrahedralizeOptions {
  double max_volume = 0.0;        // TetGen -a: largest tet volume; 0 = unbounded
  double radius_edge_ratio = 1.5; // TetGen -q: quality bound; 0 = no quality refinement
  double min_dihedral_deg = 10.0; // TetGen -q.../d: smallest dihedral angle aimed for
  bool verbose = false;           // let TetGen's own output through
};

// Meshes the inside of `surface`. `source` names the input in error messages.
// Throws InputError for open, self-intersecting or degenerate surfaces.
TetMesh tetrahedralize(const SurfaceMesh& surface, const TetrahedralizeOptions& options, const std::string& source);

}  // namespace mtcut::engine
