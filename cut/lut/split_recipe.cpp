#include "cut/lut/split_recipe.h"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "cut/lut/recipe_faces.h"
#include "cut/lut/split_bielser17.h"
#include "cut/lut/split_lut.h"
#include "cut/lut/split_realisation.h"
#include "engine/tet_geometry.h"

namespace mtcut::cut {
namespace {

using engine::kTetEdges;
using engine::Vec3;

std::string describe(const TetConfig& c) {
  static const char* names[] = {"neg", "pos", "on", "on-inactive"};
  std::string out = "key " + std::to_string(c.key()) + " (vertices";
  for (VertexState s : c.vertex) out += std::string(" ") + names[static_cast<int>(s)];
  out += ", cut edges";
  for (int k = 0; k < 6; ++k)
    if (c.edge_active(k)) out += " " + std::to_string(kTetEdges[k][0]) + std::to_string(kTetEdges[k][1]);
  return out + ")";
}

}  // namespace

const char* scheme_name(SplitScheme scheme) { return scheme == SplitScheme::kLut ? "lut" : "bielser17"; }

std::optional<SplitScheme> parse_scheme(std::string_view name) {
  if (name == "lut") return SplitScheme::kLut;
  if (name == "bielser17") return SplitScheme::kBielser17;
  return std::nullopt;
}

void orient_recipe(const TetConfig& config, const CutTrace& trace, SplitRecipe& recipe) {
  const auto pos = reference_positions(config, trace);
  auto corner = [&](int i) { return pos[make_label(LabelKind::kVertex, i)]; };
  const double whole = engine::signed_volume(corner(0), corner(1), corner(2), corner(3));
  double sum = 0;
  for (auto& t : recipe.tets) {
    double v = engine::signed_volume(pos[t[0]], pos[t[1]], pos[t[2]], pos[t[3]]);
    if (!(std::abs(v) > 1e-9 * whole))
      throw std::logic_error("split of " + describe(config) + ": a flat or undefined tet");
    if (v < 0) {
      std::swap(t[2], t[3]);
      v = -v;
    }
    sum += v;
  }
  if (std::abs(sum - whole) > 1e-9 * whole)
    throw std::logic_error("split of " + describe(config) + ": the tets do not fill the tet (volume " +
                           std::to_string(sum / whole) + " of it)");
}

void index_labels(SplitRecipe& recipe) {
  std::array<std::int16_t, kLabelCount> slot;
  slot.fill(-1);
  recipe.labels.clear();
  recipe.corner_slots.resize(recipe.tets.size());
  for (std::size_t j = 0; j < recipe.tets.size(); ++j)
    for (int c = 0; c < 4; ++c) {
      const Label l = recipe.tets[j][c];
      if (slot[l] < 0) {
        slot[l] = static_cast<std::int16_t>(recipe.labels.size());
        recipe.labels.push_back(l);
      }
      recipe.corner_slots[j][c] = static_cast<std::uint8_t>(slot[l]);
    }
}

SplitRecipe make_recipe(const TetConfig& config, SplitScheme scheme) {
  TraceOptions options;
  options.split_face_nodes = scheme == SplitScheme::kBielser17;
  const CutTrace trace = trace_cut(config, options);
  SplitRecipe recipe =
      scheme == SplitScheme::kLut ? generate_lut_split(config) : generate_bielser17_split(config);
  orient_recipe(config, trace, recipe);
  recipe.faces = recipe_piece_faces(recipe);
  index_labels(recipe);
  return recipe;
}

}  // namespace mtcut::cut
