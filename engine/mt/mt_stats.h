#pragma once
// The figures `mtcut mt` prints about an MT.

#include <cstddef>

#include "engine/mt/mt.h"

namespace mtcut::engine {

struct MtStats {
  std::size_t vertices = 0;       // shared by all resolutions
  std::size_t tets_total = 0;     // live tets of all resolutions
  std::size_t fragments = 0;      // DAG nodes, root and drain included
  std::size_t dag_depth = 0;      // arcs on the longest root -> drain path
  std::size_t finest_tets = 0;    // tets the root creates
  std::size_t coarsest_tets = 0;  // tets the drain replaces
  std::size_t bytes = 0;          // heap memory of the MT
  // How far the coarsest level's surface lies from the finest's
  // (surface_deviation.h), as a fraction of the MT's bounding-box diagonal
  // (MtBuildOptions::max_surface_deviation's): 0 with the boundary preserved.
  double coarsest_surface_deviation = 0;
};

MtStats compute_mt_stats(const Mt& mt);

}  // namespace mtcut::engine
