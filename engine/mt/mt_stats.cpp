#include "engine/mt/mt_stats.h"

#include <algorithm>
#include <vector>

#include "engine/mt/bvh.h"
#include "engine/mt/surface_deviation.h"

namespace mtcut::engine {

MtStats compute_mt_stats(const Mt& mt) {
  MtStats stats;
  stats.vertices = mt.num_vertices();
  stats.tets_total = mt.num_live_tets();
  stats.fragments = mt.num_fragments();
  stats.finest_tets = mt.root().valid() ? mt.created(mt.root()).size() : 0;
  stats.coarsest_tets = mt.drain().valid() ? mt.replaced(mt.drain()).size() : 0;
  stats.bytes = mt.bytes();
  // Longest path: relax arcs in topological order.
  std::vector<std::size_t> depth(mt.num_fragments(), 0);
  for (FragId f : mt.topological_order())
    for (TetId t : mt.created(f)) {
      const FragId c = mt.death(t);
      if (c.valid()) depth[c.index()] = std::max(depth[c.index()], depth[f.index()] + 1);
    }
  if (mt.drain().valid()) stats.dag_depth = depth[mt.drain().index()];
  // Of the diagonal the builder's bound is a fraction of (mt_builder.h).
  if (const double deviation = coarsest_surface_deviation(mt); deviation > 0)
    stats.coarsest_surface_deviation = deviation / box_of(mt.positions()).diagonal();
  return stats;
}

}  // namespace mtcut::engine
