#pragma once
// Volume meshing of a closed triangle surface through the TetGen library
// (a PLC in, a constrained quality Delaunay mesh out). TetGen runs in a
// child process: it reports faults by printing and throwing an int, it
// aborts on an assertion on some inputs, and its quality refinement can run
// away on thin features; a child's crash or overrun is one InputError line
// here, not a signal or a hang. Its added points are bounded
// (steiner_point_bound): a run that reaches the bound is meshed again with a
// looser quality bound, kept even if it too reaches it, and a note says so.

#include <functional>
#include <string>
#include <vector>

#include "engine/input_error.h"
#include "engine/surface_mesh.h"
#include "engine/tet_mesh.h"

namespace mtcut::engine {

struct TetrahedralizeOptions {
  double max_volume = 0.0;        // TetGen -a: largest tet volume; 0 = unbounded
  double radius_edge_ratio = 1.5; // TetGen -q: quality bound; 0 = no quality refinement
  double min_dihedral_deg = 10.0; // TetGen -q.../d: smallest dihedral angle aimed for
  bool verbose = false;           // let TetGen's own output through
  long max_added_points = 0;        // TetGen -S: 0 = steiner_point_bound's
  double time_limit_seconds = 300;  // a meshing still running after this is stopped and refused
  // Called about once a second while TetGen runs, with the seconds so far
  // (a progress line on a terminal); none when empty.
  std::function<void(double seconds)> progress;
};

// What TetGen refuses for the surface's geometry (it crosses itself, faces
// too close or too small for its tolerance, a crash on it), as against a
// limit it ran into (time, memory) or bad options, which stay InputError.
class SurfaceRefused : public InputError {
 public:
  using InputError::InputError;
};

// The most points TetGen may add to `surface` (TetGen -S): generous for the
// tets max_volume asks for and for quality refinement near the surface.
long steiner_point_bound(const SurfaceMesh& surface, const TetrahedralizeOptions& options);

// Meshes the inside of `surface`. `source` names the input in error
// messages and notes; `notes`, when given, receives a line for a retry with
// looser quality. Throws SurfaceRefused for open, self-intersecting or
// degenerate surfaces and for a TetGen that crashes on them, and
// InputError for a TetGen that overruns the time limit or memory (with a
// kMaxVolume hint when options.max_volume bounds the tets).
TetMesh tetrahedralize(const SurfaceMesh& surface, const TetrahedralizeOptions& options, const std::string& source,
                       std::vector<InputNote>* notes = nullptr);

}  // namespace mtcut::engine
