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

#include <span>
#include <vector>

#include "cut/tet_classifier.h"
#include "cut/vertex_factory.h"
#include "engine/tet_mesh.h"

namespace mtcut::cut {

// Before the split: edges whose two ends the cut splits, and around which
// one side of the cut would be in two parts touching only along the edge
// (the tip of an earlier cut lying in the plane while its crack crosses it).
// No copy per side can fix that, so the cutter vetoes snapping for the
// returned vertices (their ends) and classifies again.
std::vector<VertId> find_pinching_vertices(const engine::TetMesh& mesh, const CutClassifier& classifier);

// Unpinches the `candidates` of `mesh`. Copies are appended to the mesh and
// to `made` (a copy of a vertex made by this cut copies its record); tets
// given a copy are appended to `changed`. Returns the number of copies.
std::size_t unpinch_vertices(engine::TetMesh& mesh, std::span<const VertId> candidates,
                             std::vector<NewVertex>& made, std::vector<engine::TetId>& changed);

}  // namespace mtcut::cut
