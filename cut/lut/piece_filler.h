#pragma once
// Filling a polytope, given by its triangulated boundary over local labels,
// with the fewest tets whose corners are boundary points (no new point).
// Used for the pieces no single cone fits (case O). A small exhaustive
// search: the pieces have at most a dozen corners.
//
// A candidate tet must be positive in every given realisation, so the result
// does not depend on where the cut points sit; faces must pair up with
// opposite orientations, the unpaired ones must be exactly the boundary, and
// the volumes must add up to the polytope's (which rules out overlaps).

#include <optional>
#include <vector>

#include "cut/lut/split_realisation.h"

namespace mtcut::cut {

// `boundary`: triangles oriented outward. `realisations`: positions of the
// labels; the first one measures volumes. Searches up to `max_tets` tets and
// gives up after `budget` search steps.
std::optional<std::vector<std::array<Label, 4>>> fill_piece(const std::vector<std::array<Label, 3>>& boundary,
                                                            const std::vector<LabelPositions>& realisations,
                                                            int max_tets, long budget = 20000);

}  // namespace mtcut::cut
