#pragma once
// Splitting one tet: its configuration picks a recipe (SplitTable), and the
// recipe's local labels become keyed points (vertex_factory.h). This is the
// per-tet step that every cutter shares: the single-resolution mesh cutter
// here, and the MT cutter that applies it to every resolution.
//
// Pure: given the classifier's vertex states (fixed once per cut, see
// tet_classifier.h) the result depends only on the tet's four global ids,
// their positions and the polygon. Two tets sharing an edge or a face, in
// any fragment or resolution, name the points on it with the same keys and
// compute them from the same bits, so they get the same vertices.

#include <array>
#include <span>
#include <vector>

#include "cut/lut/split_table.h"
#include "cut/tet_classifier.h"
#include "cut/vertex_factory.h"

namespace mtcut::cut {

// The key of the point `label` of `tet` (global ids, sorted).
PointKey point_key(const Tet& tet, Label label);
// Where that point is: a MadeVertex's position, parents and weights (its id,
// key and rest are the numbering's). `recipe` is used for the 1:17 centre only.
MadeVertex point_source(const Tet& tet, Label label, const CutClassifier& classifier, const SplitRecipe& recipe);
// point_source of the point on local edge `edge` of `tet` at parameter t
// from its lower id (the classifier's crossing_parameter).
MadeVertex edge_point_source(const Tet& tet, int edge, double t, std::span<const Vec3> positions);

// The split of one tet, resolved to vertex ids by `factory`; the tets are
// appended to `out`. `config` must be classifier.configure(tet) and cut. Returns the case.
CutCase split_tet(const Tet& tet, const TetConfig& config, const CutClassifier& classifier, SplitTable& table,
                  VertexFactory& factory, std::vector<Tet>& out);

}  // namespace mtcut::cut
