#include "app/fragment_levels.h"

#include <algorithm>

namespace mtcut::app {

std::vector<std::int32_t> fragment_levels(const engine::Mt& mt) {
  std::vector<std::int32_t> level(mt.num_fragments(), -1);
  for (const engine::FragId f : mt.topological_order()) {
    std::int32_t l = 0;
    for (const engine::FragId p : mt.parents(f)) l = std::max(l, level[p.index()] + 1);
    level[f.index()] = l;
  }
  return level;
}

}  // namespace mtcut::app
