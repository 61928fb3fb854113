#pragma once
// The surface faces of a split's pieces, decided once per recipe from its
// local labels instead of once per split tet from vertex ids.
//
// Why per recipe. Which split-tet face a piece face lies in, and whether it
// is shared by another piece, depends only on the labels: vertex i lies on
// the three faces through i, an edge point on the two faces through its
// edge, a face point on its face, the centre on none. So the boundary mask of
// every piece is a function of the recipe and of the split tet's own mask,
// and the cutter pays a few bit operations per piece (mt_cut.cpp).

#include "cut/lut/split_labels.h"
#include "engine/mt/mt.h"

namespace mtcut::cut {

// The faces of every tet of `recipe` (oriented), in recipe order.
std::vector<PieceFaces> recipe_piece_faces(const SplitRecipe& recipe);

// The boundary mask of a piece whose split tet has mask `parent`.
inline engine::FaceMask piece_mask(const PieceFaces& faces, engine::FaceMask parent) {
  return faces.mask_for[parent & 0xFu];
}

}  // namespace mtcut::cut
