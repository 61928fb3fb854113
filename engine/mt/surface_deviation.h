#pragma once
// How far a level's surface lies from the fine one, measured.
//
// Why measured. With the boundary not preserved, the builder checks each
// collapse's move of the surface at samples against the fine surface
// (collapse.h); this measures the result the same way, on its own, so that
// a user (and the tests) read how far the coarsest tissue's outline lies
// from the organ: the two-sided (Hausdorff) distance between the outer
// surfaces of the finest and the coarsest level, each surface sampled at
// its triangles' corners, edge midpoints and centroids and each sample's
// distance taken to the nearest triangle of the other (an index over
// triangles). A preserved boundary is the same surface at every level: 0
// without a pass.

#include "engine/mt/mt.h"

namespace mtcut::engine {

// In metres; 0 for an MT without a root or a drain.
double coarsest_surface_deviation(const Mt& mt);

}  // namespace mtcut::engine
