#pragma once
// What cutting the MT changed, as data (STYLE.md 2: no callbacks into higher
// layers). The simulator reads `made_vertices` (cut/made_vertex.h) to carry
// the particles' state over (sim/state_transfer.h),
// the World reads `fragment_splits` to map its frontier (frontier_mapping.h),
// and the bench reads the counts and times.
//
// Why per call, not per cut. The time-critical cutter spreads one cut over
// several frames; every run() returns what that call changed, so the World
// can follow step by step. cut_mt() (the whole cut at once) returns one
// report for the whole cut.

#include <array>
#include <cstdint>
#include <vector>

#include "cut/made_vertex.h"
#include "engine/ids.h"
#include "engine/mt/mt.h"
#include "engine/tet_mesh.h"

namespace mtcut::cut {

using engine::FragId;
using engine::TetId;

// One MT tet replaced by its pieces R(t) (one piece when the tet was only
// relabelled onto the copy of a vertex the cut passes through).
struct TetReplacement {
  TetId old;              // killed
  FragId birth, death;    // old's fragments when it was killed (what a retraction restores)
  std::uint32_t first;    // offset of its pieces in MtChangeReport::made_tets
  std::uint32_t count;    // number of pieces
  // The configuration its split was made from (TetConfig::key; 0 for a
  // relabel): a part's front keeps a split whose configuration the grown
  // polygon leaves as it was (TimeCriticalCutter::recut).
  std::uint32_t config = 0;
};

// A fragment the cut separated: `parts[0]` is `old` itself (it keeps its id
// and the first part), the others are new fragments. Every part of a
// fragment in a frontier's set S must be in S too (frontier_mapping.h).
struct FragmentSplit {
  FragId old;
  std::vector<FragId> parts;  // k >= 2 parts, parts[0] == old
};

struct MtCutCounts {
  std::size_t split_tets = 0;        // tets replaced by a LUT split
  std::size_t relabeled_tets = 0;    // tets moved onto a split vertex's copy
  std::size_t new_tets = 0;          // pieces of the split tets
  std::size_t new_vertices = 0;
  std::size_t split_fragments = 0;   // fragments decomposed into >= 2 parts
  std::size_t new_fragments = 0;     // parts beyond the first
  std::size_t whole_fragments = 0;   // cut fragments kept whole (parts not separable, e.g. the cut's outline inside)
  std::size_t jobs = 0;              // fragment jobs processed
  double find_seconds = 0;           // BVH search and classification
  double split_seconds = 0;          // replacing the cut tets (LUT, MT and BVH edits)
  double dag_seconds = 0;            // decomposing fragments, re-attaching arcs

  void add(const MtCutCounts& o);
};

struct MtChangeReport {
  std::vector<TetReplacement> replaced;   // (n_replaced) in processing order
  std::vector<TetId> made_tets;           // pieces, grouped by `replaced`
  // Ascending ids; rest = sum weights[i] * rest(parents[i]) is stored in
  // the MT, position is where the cut put it (deformed when the World gives
  // a geometry, DESIGN.md "Which geometry is cut").
  std::vector<MadeVertex> made_vertices;
  std::vector<FragmentSplit> fragment_splits;
  std::vector<FragId> processed;          // fragments whose job ran, in order (ids before the split)
  MtCutCounts counts;

  // Appends another report (a later call of the same or the next cut).
  void append(const MtChangeReport& later);
  // Its tet and vertex ids (the made vertices' keys and parents among them)
  // through a compaction of the MT that kept every tet it names
  // (Mt::compact); fragments keep their ids.
  void renumber(const engine::Mt::Compaction& compaction);
  bool empty() const { return replaced.empty() && fragment_splits.empty(); }
  // How much the report holds, to cut it back to: what a cut appended is
  // dropped when the cut is taken back before anyone read it (the counts,
  // the work done, stay).
  struct Length {
    std::size_t replaced = 0, made_tets = 0, made_vertices = 0, fragment_splits = 0, processed = 0;
  };
  Length length() const {
    return {replaced.size(), made_tets.size(), made_vertices.size(), fragment_splits.size(), processed.size()};
  }
  void truncate(const Length& to);
};

}  // namespace mtcut::cut
