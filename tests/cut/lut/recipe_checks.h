#pragma once
// Checks of a split recipe on its own, over local labels: every cut
// configuration can be enumerated, realised with random geometry, and its
// recipe checked to tile the tet, conform on the faces and separate the
// sides. Shared by the LUT and 1:17 tests.

#include <array>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "cut/lut/cut_trace.h"
#include "cut/lut/split_configs.h"
#include "cut/lut/split_realisation.h"
#include "cut/lut/split_table.h"
#include "engine/tet_geometry.h"

namespace mtcut::cut::test {

using engine::Vec3;

// The enumeration lives in the library (split_configs.h).
using cut::all_cut_configs;

inline std::array<Vec3, kLabelCount> random_realisation(const TetConfig& c, const CutTrace& tr, std::mt19937_64& rng,
                                                        bool planar) {
  return random_positions(c, tr, rng, planar);
}

struct RecipeCheck {
  std::vector<std::string> problems;
  int components = 0;
  bool ok() const { return problems.empty(); }
};

// Checks `recipe` of `c` in the realisation `pos`: positive tets, faces
// matched inside, the tet's faces and the two sides of the cut surface
// covered exactly, no tet joining the two ends of a cut edge; counts the
// pieces (components through shared faces).
inline RecipeCheck check_recipe(const TetConfig& c, const SplitRecipe& recipe, const std::array<Vec3, kLabelCount>& pos) {
  RecipeCheck out;
  auto problem = [&](const std::string& s) {
    if (out.problems.size() < 5) out.problems.push_back(s);
  };
  const double whole = engine::signed_volume(pos[0], pos[make_label(LabelKind::kVertex, 1)],
                                             pos[make_label(LabelKind::kVertex, 2)], pos[make_label(LabelKind::kVertex, 3)]);
  double sum = 0;
  struct FaceUse {
    std::array<Label, 3> key;  // sorted labels
    int tet;
    Vec3 area;                 // outward from the tet
  };
  std::vector<FaceUse> uses;
  for (std::size_t t = 0; t < recipe.tets.size(); ++t) {
    const auto& q = recipe.tets[t];
    const double v = engine::signed_volume(pos[q[0]], pos[q[1]], pos[q[2]], pos[q[3]]);
    if (!(v > 0)) problem("tet " + std::to_string(t) + " has volume " + std::to_string(v / whole) + " of the tet");
    sum += v;
    for (int f = 0; f < 4; ++f) {
      const auto& lf = engine::kTetFaces[f];
      std::array<Label, 3> key = {q[lf[0]], q[lf[1]], q[lf[2]]};
      const Vec3 area = 0.5 * (pos[key[1]] - pos[key[0]]).cross(pos[key[2]] - pos[key[0]]);
      std::sort(key.begin(), key.end());
      uses.push_back({key, static_cast<int>(t), area});
    }
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) {
        if (label_kind(q[a]) != LabelKind::kVertex || label_kind(q[b]) != LabelKind::kVertex) continue;
        const int i = label_index(q[a]), j = label_index(q[b]);
        if (i != j && c.edge_active(edge_between(i, j)))
          problem("tet " + std::to_string(t) + " keeps the cut edge " + std::to_string(i) + std::to_string(j));
      }
  }
  if (std::abs(sum - whole) > 1e-9 * whole) problem("volumes add up to " + std::to_string(sum / whole) + " of the tet");
  std::sort(uses.begin(), uses.end(), [](const FaceUse& a, const FaceUse& b) { return a.key < b.key; });

  // Unmatched faces must tile the tet's faces, or lie on the cut surface
  // where the two sides' faces cancel.
  std::vector<int> parent(recipe.tets.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = static_cast<int>(i);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::array<Vec3, 4> face_area;
  face_area.fill(Vec3::Zero());
  Vec3 cut_area = Vec3::Zero();
  double cut_abs = 0;
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i + 1;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    const auto& key = uses[i].key;
    if (j - i == 2) {
      if ((uses[i].area + uses[i + 1].area).norm() > 1e-9) problem("a shared face is used twice the same way");
      parent[find(uses[i].tet)] = find(uses[i + 1].tet);
    } else if (j - i > 2) {
      problem("a face is shared by " + std::to_string(j - i) + " tets");
    } else {
      int on_face = -1;
      for (int f = 0; f < 4 && on_face < 0; ++f)
        if (on_tet_face(key[0], f) && on_tet_face(key[1], f) && on_tet_face(key[2], f)) on_face = f;
      if (on_face >= 0) {
        face_area[on_face] += uses[i].area;
      } else if (on_cut_surface(c, key[0]) && on_cut_surface(c, key[1]) && on_cut_surface(c, key[2])) {
        cut_area += uses[i].area;
        cut_abs += uses[i].area.norm();
      } else {
        problem("an unmatched face inside the tet");
      }
    }
    i = j;
  }
  for (int f = 0; f < 4; ++f) {
    const auto& lf = engine::kTetFaces[f];
    auto corner = [&](int i) { return pos[make_label(LabelKind::kVertex, lf[i])]; };
    const Vec3 expect = 0.5 * (corner(1) - corner(0)).cross(corner(2) - corner(0));
    if ((face_area[f] - expect).norm() > 1e-9 * expect.norm()) problem("face " + std::to_string(f) + " is not covered exactly");
  }
  if (cut_area.norm() > 1e-9 * std::max(cut_abs, 1.0)) problem("the two sides of the cut surface differ");
  std::set<int> roots;
  for (std::size_t i = 0; i < parent.size(); ++i) roots.insert(find(static_cast<int>(i)));
  out.components = static_cast<int>(roots.size());
  return out;
}

}  // namespace mtcut::cut::test
