#pragma once
// Building an MT from a fine tet mesh by half-edge collapses (DESIGN.md,
// "Building the MT"; the rules and the cost are in collapse.h).
//
// Why rounds. Collapsing strictly one at a time, least error first, chains
// every collapse to the previous ones nearby and the DAG gets as deep as the
// number of collapses. Instead each round takes the cheapest candidates
// (the cheapest `round_fraction` of all valid collapses, least error first)
// and applies those whose 1-rings are disjoint: such collapses neither touch
// each other's tets nor change each other's validity or cost, so they are
// independent fragments and the round adds one level to the DAG. A constant
// fraction of the vertices goes per round, so the depth grows like log(n).
// Only the vertices whose star a collapse changed are re-evaluated.
//
// Each collapse (or group of collapses_per_fragment) is one fragment; the
// root holds the fine mesh and the drain replaces whatever is left when the
// build stops.

#include <cstddef>

#include "engine/mt/collapse.h"
#include "engine/mt/mt.h"
#include "engine/tet_mesh.h"

namespace mtcut::engine {

struct MtBuildOptions {
  // Stop once the coarsest mesh has at most this many tets; 0: simplify as
  // far as valid collapses go.
  std::size_t target_coarsest_tets = 0;
  // Stop after this many collapses (the MT then has collapses + 2
  // fragments); 0: no limit.
  std::size_t max_collapses = 0;
  // Keep the surface exactly (flat regions and straight creases may still be
  // simplified); every frontier then has the fine mesh's volume. Off: the
  // surface may move by up to the error of each collapse and
  // max_surface_deviation, from the fine surface (collapse.h).
  bool preserve_boundary = true;
  // With preserve_boundary off: how far the surface may move in all, as a
  // fraction of the fine mesh's bounding-box diagonal (every level's
  // surface then lies within it of the fine one; each collapse's move is
  // also bounded by its error). Infinite: by the collapses' errors alone.
  double max_surface_deviation = 0.01;
  // Smallest tet_quality a collapse may create (or the worst quality of the
  // tets it replaces, when that is lower).
  double min_quality = 0.05;
  // Each round draws its collapses from this cheapest fraction of the valid
  // candidates (smaller: closer to strict least-error order, deeper DAG).
  double round_fraction = 0.25;
  // Collapses grouped into one fragment: the cheapest collapse, then the
  // cheapest collapses of vertices around it, applied one after the other
  // (a connected region re-tessellated in one step; the tets made and
  // replaced inside it never appear in the MT). 1: one collapse, one fragment.
  int collapses_per_fragment = 1;
};

struct MtBuildReport {
  std::size_t rounds = 0;
  std::size_t collapses = 0;
  double seconds = 0.0;
  CollapseRejections rejections;
};

// The MT of `fine` (which must be valid: TetMesh::validate()).
Mt build_mt(const TetMesh& fine, const MtBuildOptions& options = {}, MtBuildReport* report = nullptr);

}  // namespace mtcut::engine
