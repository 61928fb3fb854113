#pragma once
// Local point labels of a split tet: DESIGN.md's LUT encoding, generalised
// so that one byte names every point a split can use:
//   vertex i            (i = 0..3; a split vertex has a copy per side),
//   edge point on e_k   (k = 0..5, kTetEdges order; one copy per side),
//   face point on f_i   (the face opposite vertex i; one copy, or one per
//                        side for the 1:17 scheme's split face nodes),
//   the centre          (1:17 only; one copy, or one per side).
// DESIGN.md's 4+2k / 5+2k name edge copies by endpoint (lower / higher local
// vertex); here they are named by the side of the plane (negative /
// positive), which is what a global key can use. 16+i is face(i).

#include <array>
#include <cstdint>
#include <vector>

#include "cut/tet_classifier.h"

namespace mtcut::cut {

enum class LabelKind : std::uint8_t { kVertex = 0, kEdge = 1, kFace = 2, kCentre = 3 };
enum class LabelSide : std::uint8_t { kNone = 0, kNeg = 1, kPos = 2 };

using Label = std::uint8_t;  // kind (2 bits) | index << 2 (3 bits) | side << 5 (2 bits)

constexpr Label make_label(LabelKind kind, int index, LabelSide side = LabelSide::kNone) {
  return static_cast<Label>(static_cast<int>(kind) | index << 2 | static_cast<int>(side) << 5);
}
constexpr LabelKind label_kind(Label l) { return static_cast<LabelKind>(l & 3); }
constexpr int label_index(Label l) { return l >> 2 & 7; }
constexpr LabelSide label_side(Label l) { return static_cast<LabelSide>(l >> 5 & 3); }
constexpr Label with_side(Label l, LabelSide side) {
  return static_cast<Label>((l & 0x1f) | static_cast<int>(side) << 5);
}
constexpr Label unsided(Label l) { return static_cast<Label>(l & 0x1f); }
constexpr LabelSide opposite(LabelSide s) {
  return s == LabelSide::kNeg ? LabelSide::kPos : s == LabelSide::kPos ? LabelSide::kNeg : LabelSide::kNone;
}
constexpr LabelSide side_of(VertexState s) {
  return s == VertexState::kNeg ? LabelSide::kNeg : s == VertexState::kPos ? LabelSide::kPos : LabelSide::kNone;
}

inline constexpr int kLabelCount = 128;

// The split of one tet configuration: tets over local labels, each
// positively oriented when the tet (0, 1, 2, 3) is.
// The boundary mask of one recipe tet (a piece) for each boundary mask of
// the split tet (recipe_faces.h): a piece face inside a face of the split
// tet is surface exactly when that face is; a face of the cut surface
// always is.
struct PieceFaces {
  std::array<std::uint8_t, 16> mask_for{};  // [split tet's mask] -> piece's mask
};

struct SplitRecipe {
  CutCase kind = CutCase::kA;
  std::vector<std::array<Label, 4>> tets;
  std::vector<Label> centre_of;  // the centre, when used (1:17, some LUT splits): centroid of these (unsided) points
  std::vector<PieceFaces> faces;  // (tets) filled by make_recipe once the tets are oriented
  // The distinct labels of `tets` in the order the tets first use them, and
  // each tet's corners as indexes into `labels` (index_labels): a split
  // finds each label's vertex once, then fills its pieces' corners by index.
  std::vector<Label> labels;
  std::vector<std::array<std::uint8_t, 4>> corner_slots;  // (tets)
};

// Fills recipe.labels and recipe.corner_slots from recipe.tets.
void index_labels(SplitRecipe& recipe);

}  // namespace mtcut::cut
