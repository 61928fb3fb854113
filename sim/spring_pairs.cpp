#include "sim/spring_pairs.h"

namespace mtcut::sim {

void PairedSide::build(std::size_t n, const std::vector<std::int32_t>& key,
                       const std::vector<std::int32_t>& other_end) {
  const std::size_t m = key.size();
  std::vector<std::int32_t> count(n, 0);
  for (std::size_t s = 0; s < m; ++s) ++count[static_cast<std::size_t>(key[s])];
  start.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) start[i + 1] = start[i] + (count[i] + 1) / 2;
  const auto pairs = static_cast<std::size_t>(start[n]);
  other.assign(2 * pairs, static_cast<std::int32_t>(n));
  blocks.assign(pairs, BlockPair{});
  lane_spring.assign(2 * pairs, -1);
  std::vector<std::int32_t> next(n);
  for (std::size_t i = 0; i < n; ++i) next[i] = 2 * start[i];
  for (std::size_t s = 0; s < m; ++s) {  // in spring order: each particle's springs keep their order
    const std::int32_t k = next[static_cast<std::size_t>(key[s])]++;
    lane_spring[static_cast<std::size_t>(k)] = static_cast<std::int32_t>(s);
    other[static_cast<std::size_t>(k)] = other_end[s];
  }
}

}  // namespace mtcut::sim
