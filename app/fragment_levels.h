#pragma once
// The level of each fragment of the MT, for the LOD colours of the viewer
// and the fragment_level cell data of `mtcut run`'s snapshots: the root (the
// finest mesh) is level 0, and a fragment sits one level above the highest of
// its parents, so the level counts the simplification rounds behind a tet:
// the coarser the tet, the higher its level.

#include <cstdint>
#include <vector>

#include "engine/mt/mt.h"

namespace mtcut::app {

// (n_fragments) level of each fragment; -1 for fragments off the DAG.
std::vector<std::int32_t> fragment_levels(const engine::Mt& mt);

}  // namespace mtcut::app
