#pragma once
// The level of each fragment of the MT for the LOD view: the root (the
// finest mesh) is level 0, and a fragment sits one level above the highest
// of its parents, so the level counts the simplification rounds behind a
// tet: the coarser the tet, the higher its level.

#include <cstdint>
#include <vector>

#include "engine/mt/mt.h"

namespace mtcut::app::view {

struct FragmentLevels {
  std::vector<std::int32_t> level;  // (n_fragments) -1 for fragments off the DAG
  std::int32_t max_level = 0;       // over fragments that create tets
};

FragmentLevels compute_fragment_levels(const engine::Mt& mt);

}  // namespace mtcut::app::view
