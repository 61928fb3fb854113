// The boundary masks of split pieces, decided per recipe from labels
// (recipe_faces.h), against geometry: in a random planar realisation of
// every configuration, a piece face is surface exactly when it lies in a
// surface face of the split tet, or in the cut plane on one piece only;
// every other face is shared by two pieces.
#include "cut/lut/recipe_faces.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "cut/lut/split_table.h"
#include "engine/tet_geometry.h"
#include "tests/cut/lut/recipe_checks.h"

namespace mtcut::cut {
namespace {

using engine::kTetFaces;
using test::all_cut_configs;
using test::random_realisation;

struct FaceRef {
  std::array<Label, 3> labels;  // sorted
};

FaceRef face_of(const std::array<Label, 4>& tet, int f) {
  FaceRef r;
  for (int i = 0; i < 3; ++i) r.labels[i] = tet[kTetFaces[f][i]];
  std::sort(r.labels.begin(), r.labels.end());
  return r;
}

void check_scheme(SplitScheme scheme) {
  std::mt19937_64 rng(77);
  std::size_t faces_checked = 0;
  for (const TetConfig& c : all_cut_configs(6)) {
    const SplitRecipe recipe = make_recipe(c, scheme);
    ASSERT_EQ(recipe.faces.size(), recipe.tets.size());
    TraceOptions options;
    options.split_face_nodes = scheme == SplitScheme::kBielser17;
    const LabelPositions pos = random_realisation(c, trace_cut(c, options), rng, true);
    const auto corner = [&](int i) { return pos[make_label(LabelKind::kVertex, i)]; };
    const double scale = std::abs(volume6(corner(0), corner(1), corner(2), corner(3)));
    // The cut plane, through the recipe's points that lie on it (cut points
    // and vertices on the cut): the three spanning the largest triangle.
    std::vector<engine::Vec3> on_cut;
    for (const auto& t : recipe.tets)
      for (Label l : t)
        if (label_kind(l) != LabelKind::kVertex || is_on(c.vertex[label_index(l)])) on_cut.push_back(pos[l]);
    engine::Vec3 normal = engine::Vec3::Zero(), origin = engine::Vec3::Zero();
    for (std::size_t a = 0; a < on_cut.size(); ++a)
      for (std::size_t b = a + 1; b < on_cut.size(); ++b)
        for (std::size_t d = b + 1; d < on_cut.size(); ++d) {
          const engine::Vec3 n = (on_cut[b] - on_cut[a]).cross(on_cut[d] - on_cut[a]);
          if (n.squaredNorm() > normal.squaredNorm()) normal = n, origin = on_cut[a];
        }
    ASSERT_GT(normal.squaredNorm(), 0.0);
    normal.normalize();
    const double size = (corner(1) - corner(0)).norm();
    const auto in_cut_plane = [&](const std::array<Label, 4>& t, int f) {
      for (int i = 0; i < 3; ++i)
        if (std::abs(normal.dot(pos[t[kTetFaces[f][i]]] - origin)) > 1e-9 * size) return false;
      return true;
    };
    std::vector<FaceRef> all;
    for (const auto& t : recipe.tets)
      for (int f = 0; f < 4; ++f) all.push_back(face_of(t, f));
    for (std::size_t j = 0; j < recipe.tets.size(); ++j) {
      for (int f = 0; f < 4; ++f) {
        const FaceRef face = face_of(recipe.tets[j], f);
        // The split tet's faces this face lies in (all three points on it).
        unsigned within = 0;
        for (int g = 0; g < 4; ++g) {
          bool on = true;
          for (int i = 0; i < 3; ++i) {
            const engine::Vec3 p = pos[recipe.tets[j][kTetFaces[f][i]]];
            on = on && std::abs(volume6(corner(kTetFaces[g][0]), corner(kTetFaces[g][1]), corner(kTetFaces[g][2]), p)) <
                           1e-9 * scale;
          }
          if (on) within |= 1u << g;
        }
        int same_labels = 0;
        for (const FaceRef& other : all) same_labels += other.labels == face.labels;
        const bool in_cut = within == 0 && in_cut_plane(recipe.tets[j], f);
        if (within == 0 && !in_cut) {
          ASSERT_EQ(same_labels, 2) << "an inner face off the cut not shared by two pieces";
        }
        for (unsigned parent = 0; parent < 16; ++parent) {
          // In the cut and on one piece only: a face of the cut surface (one
          // side's; a face of the plane shared by two pieces lies beyond the
          // polygon's outline, inside the tet).
          const bool surface = (within & parent) != 0 || (in_cut && same_labels == 1);
          ASSERT_EQ((piece_mask(recipe.faces[j], static_cast<engine::FaceMask>(parent)) >> f & 1u) != 0, surface)
              << "piece " << j << " face " << f << " parent mask " << parent;
        }
        ++faces_checked;
      }
    }
  }
  EXPECT_GT(faces_checked, 1000u);
}

TEST(RecipeFaces, LutMasksMatchTheGeometry) { check_scheme(SplitScheme::kLut); }
TEST(RecipeFaces, BielserMasksMatchTheGeometry) { check_scheme(SplitScheme::kBielser17); }

}  // namespace
}  // namespace mtcut::cut
