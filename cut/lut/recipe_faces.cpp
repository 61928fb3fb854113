#include "cut/lut/recipe_faces.h"

#include <algorithm>

#include "engine/tet_geometry.h"

namespace mtcut::cut {
namespace {

using engine::kTetEdges;
using engine::kTetFaces;

// Bit j: the point `l` lies on face j of the split tet.
std::uint8_t faces_holding(Label l) {
  const int i = label_index(l);
  switch (label_kind(l)) {
    case LabelKind::kVertex: return static_cast<std::uint8_t>(0xF & ~(1u << i));
    case LabelKind::kEdge: return static_cast<std::uint8_t>(0xF & ~(1u << kTetEdges[i][0]) & ~(1u << kTetEdges[i][1]));
    case LabelKind::kFace: return static_cast<std::uint8_t>(1u << i);
    case LabelKind::kCentre: return 0;
  }
  return 0;
}

std::array<Label, 3> sorted_face(const std::array<Label, 4>& tet, int f) {
  std::array<Label, 3> face = {tet[kTetFaces[f][0]], tet[kTetFaces[f][1]], tet[kTetFaces[f][2]]};
  std::sort(face.begin(), face.end());
  return face;
}

}  // namespace

std::vector<PieceFaces> recipe_piece_faces(const SplitRecipe& recipe) {
  std::vector<std::array<Label, 3>> all;
  for (const auto& t : recipe.tets)
    for (int f = 0; f < 4; ++f) all.push_back(sorted_face(t, f));
  std::sort(all.begin(), all.end());
  std::vector<PieceFaces> out(recipe.tets.size());
  for (std::size_t j = 0; j < recipe.tets.size(); ++j) {
    const auto& t = recipe.tets[j];
    std::uint8_t cut = 0;                 // faces in the cut surface
    std::array<std::uint8_t, 4> within{};  // faces of the split tet each face lies in
    for (int f = 0; f < 4; ++f) {
      const auto& fv = kTetFaces[f];
      within[f] = faces_holding(t[fv[0]]) & faces_holding(t[fv[1]]) & faces_holding(t[fv[2]]);
      if (within[f] != 0) continue;
      const auto face = sorted_face(t, f);
      const auto range = std::equal_range(all.begin(), all.end(), face);
      if (range.second - range.first == 1) cut = static_cast<std::uint8_t>(cut | 1u << f);
    }
    for (unsigned parent = 0; parent < 16; ++parent) {
      std::uint8_t mask = cut;
      for (int f = 0; f < 4; ++f)
        if (within[f] & parent) mask = static_cast<std::uint8_t>(mask | 1u << f);
      out[j].mask_for[parent] = mask;
    }
  }
  return out;
}

}  // namespace mtcut::cut
