#pragma once
// Decompose(Sigma_i) and the re-attachment of its arcs (paper, section 4,
// UpdateProcessFragment / UpdateIncomingArcs / UpdateOutgoingArcs), for one
// fragment whose tets the cut has already replaced.
//
// Why this shape. mtcut stores the paper's expanded arc list: tet t is the
// arc (birth(t), death(t)). Splitting a tet t (R(t), mt_cut.h) gives its
// pieces t's birth and death, which is UpdateOutgoingArcs' "replace (t,
// Sigma_k) with {(t', Sigma_k)}" for a parent, and its "add (t', part of
// Sigma_k)" once Sigma_k is separated happens here, when Sigma_k's parts
// take the pieces. The MT cutter splits every cut tet of created(f) and of
// replaced(f) before it decomposes f, so both tessellations of f's region
// are final when f is decomposed, whatever the order of the fragments:
// each part takes the created tets it is made of (births) and the replaced
// tets of its region (deaths: UpdateIncomingArcs). Nothing else in the MT
// changes, so fragments can be processed in any order with the same result
// up to the numbering of new fragments.
//
// Parts are the groups of created(f) + replaced(f) connected through shared
// vertices. The cut duplicates every vertex of its surface (an edge point per
// side, a copy per side of a vertex it passes through), so tets on opposite
// sides of a cut face never share a vertex, while tets on one side of f's
// region are joined face to face (the connectivity the paper means); the
// replaced tets, the other tessellation of the same region, join the part
// whose region they lie in through the region's boundary vertices, which both
// tessellations share. Only a cut whose outline passes through the region
// (the paper's IsSplit is false) puts a single-copy point (a face point) in
// it: then the sides stay joined, and f stays whole, as in the paper.
//
// A grouping that would leave a part creating or replacing nothing (which
// cannot be a fragment) keeps f whole instead; the count is reported.

#include <cstdint>
#include <vector>

#include "engine/mt/mt.h"

namespace mtcut::cut {

using engine::FragId;
using engine::Mt;
using engine::TetId;

enum class DecomposeOutcome : std::uint8_t { kConnected, kSplit, kKeptWhole };

struct Decomposition {
  DecomposeOutcome outcome = DecomposeOutcome::kConnected;
  std::vector<FragId> parts;  // kSplit: k >= 2 parts, parts[0] == f (it keeps its id)
};

// Scratch reused between calls: nothing is allocated per fragment once warm.
struct DecompositionScratch {
  std::vector<std::int32_t> vertex_owner;  // (n_vertices) first tet index holding the vertex, -1 none
  std::vector<engine::VertId> touched;     // vertices to reset (a prefix; sized for four per tet)
  std::vector<std::int32_t> parent;        // union-find over created(f) then replaced(f)
  std::vector<std::int32_t> group;         // (tets) group of each root, then of each tet
  std::vector<std::int32_t> created_count, replaced_count;  // per group
};

// Decomposes f (neither the root nor the drain) into its parts: parts[0]
// keeps f, the others are new fragments appended to the MT; each part
// creates and replaces its group's tets.
Decomposition decompose_fragment(Mt& mt, FragId f, DecompositionScratch& scratch);

}  // namespace mtcut::cut
