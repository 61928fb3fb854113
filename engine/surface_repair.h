#pragma once
// Repair of the surfaces people have (touching or crossing themselves in a
// few faces, holes, non-manifold seams, duplicate points, faces turned the
// wrong way, several parts) into a closed, manifold, outward,
// self-intersection-free surface that TetGen meshes, through CGAL's polygon
// mesh processing. The first of these that gives such a surface is kept:
//   1. the soup's own repair, exact: duplicate points merged, degenerate and
//      twice-given faces dropped, faces turned one way, borders stitched;
//   2. holes closed by refined, faired patches;
//   3. self-intersections resolved: the union of overlapping parts (exact),
//      else the crossing faces replaced locally (within 5% of the volume);
//   4. an alpha wrap of the whole (alpha = diagonal / 75, offset =
//      diagonal / 2250): watertight by construction, a little larger.

#include <cstddef>
#include <string>

#include "engine/surface_mesh.h"

namespace mtcut::engine {

struct SurfaceRepair {
  enum class Step { kNone, kSoup, kHoles, kSelfIntersections, kWrap };
  Step step = Step::kNone;       // kNone: the surface was fit to mesh as it was
  std::size_t faces_in = 0, faces_out = 0;
  std::size_t points_merged = 0;  // duplicate or unused points dropped
  std::size_t faces_dropped = 0;  // degenerate or twice-given faces
  std::size_t faces_flipped = 0;  // turned to agree with their neighbours
  std::size_t holes_closed = 0;
  bool input_closed = false;      // the input enclosed a volume (every edge on two faces)
  double volume_change = 0;       // relative, against the input's volume when it was closed
  double max_distance = 0;        // farthest point of the result from the input surface (metres)

  bool changed() const { return step != Step::kNone; }
  // One line: "SOURCE: repaired (...): ...".
  std::string describe(const std::string& source) const;
};

// Repairs `surface` in place when it is not fit to mesh (see above); with
// `wrap` the alpha wrap is used whatever the earlier steps give (for a
// surface TetGen refused after them). Throws InputError naming `source`
// when no step gives a surface fit to mesh.
SurfaceRepair repair_surface(SurfaceMesh& surface, const std::string& source, bool wrap = false);

}  // namespace mtcut::engine
