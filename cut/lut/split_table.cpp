#include "cut/lut/split_table.h"

#include <algorithm>
#include <atomic>
#include <deque>
#include <mutex>
#include <vector>

#include "cut/lut/baked_lut.h"
#include "cut/lut/split_configs.h"

namespace mtcut::cut {
namespace {

constexpr std::size_t kKeyCount = std::size_t{1} << 20;

// The baked recipe of `key`; false when not baked.
bool baked_recipe(std::uint32_t key, SplitRecipe& recipe) {
  const BakedLut lut = baked_lut();
  const auto it = std::lower_bound(lut.entries.begin(), lut.entries.end(), key,
                                   [](const BakedLutEntry& e, std::uint32_t k) { return e.key < k; });
  if (it == lut.entries.end() || it->key != key) return false;
  recipe.kind = static_cast<CutCase>(it->kind);
  const auto tets = lut.tets.subspan(it->first, it->count);
  recipe.tets.assign(tets.begin(), tets.end());
  const auto faces = lut.faces.subspan(it->first, it->count);
  recipe.faces.assign(faces.begin(), faces.end());
  const auto centre = lut.centres.subspan(it->centre_first, it->centre_count);
  recipe.centre_of.assign(centre.begin(), centre.end());
  index_labels(recipe);
  return true;
}

}  // namespace

struct SplitTable::Store {
  std::mutex mutex;                              // guards making recipes
  std::vector<std::atomic<std::int32_t>> index;  // (2^20) key -> recipe, -1 = not made yet
  std::deque<SplitRecipe> recipes;               // stable addresses

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
  // The LUT shares one entry between the orders that do not matter (its
  // rule ignores them there: tested); the 1:17 reference keys every order.
  const std::uint32_t key = scheme_ == SplitScheme::kLut ? table_key(config) : config.key();
  std::int32_t slot = store_->index[key].load(std::memory_order_acquire);
  if (slot < 0) {
    std::lock_guard<std::mutex> lock(store_->mutex);
    slot = store_->index[key].load(std::memory_order_relaxed);
    if (slot < 0) {
      SplitRecipe recipe;
      if (scheme_ != SplitScheme::kLut || !baked_recipe(key, recipe)) recipe = make_recipe(config, scheme_);
      store_->recipes.push_back(std::move(recipe));
      slot = static_cast<std::int32_t>(store_->recipes.size() - 1);
      store_->index[key].store(slot, std::memory_order_release);
    }
  }
  return store_->recipes[static_cast<std::size_t>(slot)];
}

}  // namespace mtcut::cut
