#pragma once
// After a cut, a vertex whose star (the tets around it) falls into several
// parts joined only through the vertex gets one copy per part.
//
// Why. Splitting a vertex the cut passes through gives it one copy per side
// of the plane. That is enough for a vertex whose star is a ball or a
// half-ball, but not for one on the tip of an earlier cut that the new cut
// crosses (a face point of a previous stroke, snapped onto this one): there
// one side of the plane holds two wedges separated by the old crack, and
// sharing one vertex (or one edge) would pinch the surface into a
// non-manifold one. Giving each face-connected part of the star its own copy
// is the split the topology asks for.

#include <cstdint>
#include <span>
#include <vector>

#include "cut/tet_classifier.h"
#include "cut/vertex_factory.h"
#include "engine/tet_mesh.h"

namespace mtcut::cut {

// Before the split: edges whose two ends the cut splits, and around which
// one side of the cut would be in two parts touching only along the edge
// (the tip of an earlier cut near the plane, its crack bent across it by
// that cut's snapping). No copy per side fixes that. Either the vertices
// that put the smaller parts on that side are near the plane, and pulling
// them onto the cut removes those parts (the continuing stroke then follows
// the old crack), or the edge's ends are kept off the cut. The cutter
// applies the fix and classifies again.
struct PinchFix {
  std::vector<VertId> pull_in;  // snap onto the cut
  std::vector<VertId> veto;     // keep off the cut
  bool empty() const { return pull_in.empty() && veto.empty(); }
};
// `nearby`: the tets the cut may touch (all tets holding a vertex on the cut).
PinchFix find_pinches(const engine::TetMesh& mesh, const CutClassifier& classifier,
                      const std::vector<std::uint32_t>& nearby);

// Unpinches the `candidates` of `mesh`, whose tets are all among `nearby`.
// Copies are appended to the mesh and to `made` (a copy of a vertex made by
// this cut copies its record); tets given a copy are appended to `changed`.
// Returns the number of copies.
std::size_t unpinch_vertices(engine::TetMesh& mesh, std::span<const VertId> candidates,
                             const std::vector<std::uint32_t>& nearby, std::vector<MadeVertex>& made,
                             std::vector<engine::TetId>& changed);

}  // namespace mtcut::cut
