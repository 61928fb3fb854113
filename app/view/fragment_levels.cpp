#include "app/view/fragment_levels.h"

#include <algorithm>

namespace mtcut::app::view {

FragmentLevels compute_fragment_levels(const engine::Mt& mt) {
  FragmentLevels out;
  out.level.assign(mt.num_fragments(), -1);
  for (engine::FragId f : mt.topological_order()) {
    std::int32_t level = 0;
    for (engine::FragId p : mt.parents(f)) level = std::max(level, out.level[p.index()] + 1);
    out.level[f.index()] = level;
    if (!mt.created(f).empty()) out.max_level = std::max(out.max_level, level);
  }
  return out;
}

}  // namespace mtcut::app::view
