#pragma once
// Storage that one cut of the MT after another reuses.
//
// Why. A per-frame scalpel step cuts a few dozen tets of an MT holding tens
// of thousands of vertices; per-vertex arrays allocated and cleared for
// every cut would make its cost grow with the MT, not with the cut. Each
// array here is sized once to the largest MT seen and handed back clean:
// whoever writes an entry lists it and resets it when done. One cut uses a
// workspace at a time (the time-critical cutter runs its cuts in order).

#include <cstdint>
#include <vector>

#include "cut/mt/fragment_decomposition.h"
#include "cut/tet_classifier.h"
#include "engine/validation.h"

namespace mtcut::cut {

struct MtCutWorkspace {
  CutClassifier::Scratch classifier;   // the search's vertex states
  std::vector<std::uint8_t> separating;  // (>= n_vertices) 1: the cut splits the vertex; all 0 between cuts
  DecompositionScratch decomposition;  // the DAG update's
  std::vector<std::int32_t> pending_of;  // (>= n_tets) index among the cut's pending tets; all -1 between cuts
  std::vector<std::uint64_t> id_bits;  // (>= n_tets / 64) the search's sort of tet and fragment ids; all 0 between cuts
  std::vector<std::int32_t> job_of_fragment;  // (>= n_fragments) the search's job of a fragment; all -1 between cuts

  // Room for an MT of `vertices`, `tets` and `fragments` (between cuts):
  // every array sized, pristine, so that no cut grows one.
  void reserve(std::size_t vertices, std::size_t tets, std::size_t fragments);
  // Handed back clean (between cuts): every entry pristine. O(n_vertices), for tests.
  engine::ValidationReport validate() const;
};

}  // namespace mtcut::cut
