#pragma once
// Where a cut drawn on the deformed tissue goes in the MT's rest space.
//
// Why the MT is cut in rest space. DESIGN.md proposes computing the cut on
// deformed positions (a hidden vertex carried by the frontier tet around it)
// and reusing each edge parameter in rest space, claiming that all
// resolutions agree. They do not: a coarse tet's deformed shape is the affine
// interpolation of its corners, not the deformation of the fine tets inside
// it, so the crack a deformed-space plane leaves in a coarse tet and in the
// fine tets of the same fragment are different surfaces in rest space. The
// two sides of a fragment then no longer hold the same volume (Mt::validate
// reports it), and a frontier mixing resolutions along the crack overlaps or
// leaves gaps. A plane in rest space is the same surface at every
// resolution, and the cutter is exact there.
//
// So the polygon the blade swept (on the deformed tissue) is carried to rest
// space by the affine map that best fits the deformation near it (least
// squares over the simulated vertices within `reach` of it). The cut lands
// where the user cut up to the non-affine part of the deformation across the
// polygon: exact for a moved, rotated, sheared or stretched region, a small
// offset where the tissue bends strongly under the blade.

#include <span>

#include "cut/cut_polygon.h"
#include "engine/predicates.h"

namespace mtcut::sim {

using engine::Vec3;

struct RestSpaceCutDef {
  double reach = 0.1;          // of the polygon's diameter: vertices nearer than this fit the map
  std::size_t min_points = 12; // fewer: the reach doubles (up to all vertices)
};

// `rest` and `deformed`: the same simulated vertices in both spaces. Returns
// the polygon unchanged when no four vertices span a volume near it (it
// misses the tissue) or the fitted map is degenerate.
cut::CutPolygon rest_space_polygon(const cut::CutPolygon& deformed_polygon, std::span<const Vec3> rest,
                                   std::span<const Vec3> deformed, const RestSpaceCutDef& def = {});

}  // namespace mtcut::sim
