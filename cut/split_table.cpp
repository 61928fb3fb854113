#include "cut/split_table.h"

#include <atomic>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <string>

#include "cut/recipe_faces.h"
#include "cut/split_bielser17.h"
#include "cut/split_lut.h"
#include "cut/split_realisation.h"
#include "engine/tet_geometry.h"

namespace mtcut::cut {
namespace {

using engine::kTetEdges;
using engine::Vec3;

constexpr std::size_t kKeyCount = std::size_t{1} << 20;


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

SplitRecipe make_recipe(const TetConfig& config, SplitScheme scheme) {
  TraceOptions options;
  options.split_face_nodes = scheme == SplitScheme::kBielser17;
  const CutTrace trace = trace_cut(config, options);
  SplitRecipe recipe =
      scheme == SplitScheme::kLut ? generate_lut_split(config) : generate_bielser17_split(config);
  orient_recipe(config, trace, recipe);
  recipe.faces = recipe_piece_faces(recipe);
  return recipe;
}

struct SplitTable::Store {
  std::mutex mutex;                            // guards generation
  std::vector<std::atomic<std::int32_t>> index;  // (2^20) key -> recipe, -1 = not generated yet
  std::deque<SplitRecipe> recipes;             // stable addresses

  Store() : index(kKeyCount) {
    for (auto& slot : index) slot.store(-1, std::memory_order_relaxed);
  }
};

SplitTable::SplitTable(SplitScheme scheme) : scheme_(scheme) {
  static Store lut, bielser;
  store_ = scheme == SplitScheme::kLut ? &lut : &bielser;
}

std::size_t SplitTable::generated() const {
  std::lock_guard<std::mutex> lock(store_->mutex);
  return store_->recipes.size();
}

const SplitRecipe& SplitTable::recipe(const TetConfig& config) {
  const std::uint32_t key = config.key();
  std::int32_t slot = store_->index[key].load(std::memory_order_acquire);
  if (slot < 0) {
    std::lock_guard<std::mutex> lock(store_->mutex);
    slot = store_->index[key].load(std::memory_order_relaxed);
    if (slot < 0) {
      store_->recipes.push_back(make_recipe(config, scheme_));
      slot = static_cast<std::int32_t>(store_->recipes.size() - 1);
      store_->index[key].store(slot, std::memory_order_release);
    }
  }
  return store_->recipes[static_cast<std::size_t>(slot)];
}

}  // namespace mtcut::cut
