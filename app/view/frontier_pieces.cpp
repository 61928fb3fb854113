#include "app/view/frontier_pieces.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <unordered_map>

#include "engine/tet_geometry.h"

namespace mtcut::app::view {
namespace {

// Union-find over dense indices, path halving.
struct DisjointSets {
  std::vector<std::int32_t> parent;
  explicit DisjointSets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::int32_t find(std::int32_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
  void join(std::int32_t a, std::int32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

// A face by its sorted vertex ids (FNV-1a hash of the three).
struct FaceKey {
  std::array<std::int32_t, 3> v;
  bool operator==(const FaceKey&) const = default;
};
struct FaceKeyHash {
  std::size_t operator()(const FaceKey& k) const noexcept {
    std::uint64_t h = 1469598103934665603ull;
    for (std::int32_t x : k.v) h = (h ^ static_cast<std::uint32_t>(x)) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

}  // namespace

FrontierPieces find_frontier_pieces(const engine::Mt& mt, const engine::Frontier& frontier) {
  const auto tets = frontier.tets();
  DisjointSets sets(tets.size());
  std::unordered_map<FaceKey, std::int32_t, FaceKeyHash> first_owner;
  first_owner.reserve(tets.size() * 3);
  for (std::size_t i = 0; i < tets.size(); ++i) {
    const engine::Tet& tet = mt.tet(tets[i]);
    for (const auto& face : engine::kTetFaces) {
      FaceKey key{{tet[face[0]].value, tet[face[1]].value, tet[face[2]].value}};
      std::sort(key.v.begin(), key.v.end());
      const auto [it, inserted] = first_owner.try_emplace(key, static_cast<std::int32_t>(i));
      if (!inserted) sets.join(it->second, static_cast<std::int32_t>(i));
    }
  }

  // Roots -> provisional ids in order of first tet, then renumber by size.
  std::vector<std::int32_t> root_id(tets.size(), -1);
  std::vector<std::size_t> sizes;
  std::vector<std::int32_t> provisional(tets.size());
  for (std::size_t i = 0; i < tets.size(); ++i) {
    const std::int32_t r = sets.find(static_cast<std::int32_t>(i));
    if (root_id[r] < 0) {
      root_id[r] = static_cast<std::int32_t>(sizes.size());
      sizes.push_back(0);
    }
    provisional[i] = root_id[r];
    ++sizes[root_id[r]];
  }
  std::vector<std::int32_t> smallest_tet(sizes.size(), INT32_MAX);
  for (std::size_t i = 0; i < tets.size(); ++i)
    smallest_tet[provisional[i]] = std::min(smallest_tet[provisional[i]], tets[i].value);
  std::vector<std::int32_t> order(sizes.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::int32_t a, std::int32_t b) {
    return sizes[a] != sizes[b] ? sizes[a] > sizes[b] : smallest_tet[a] < smallest_tet[b];
  });
  std::vector<std::int32_t> final_id(sizes.size());
  for (std::size_t k = 0; k < order.size(); ++k) final_id[order[k]] = static_cast<std::int32_t>(k);

  FrontierPieces out;
  out.tet_piece.assign(mt.num_tets(), -1);
  out.piece_tets.resize(sizes.size());
  for (std::size_t k = 0; k < order.size(); ++k) out.piece_tets[k] = sizes[order[k]];
  for (std::size_t i = 0; i < tets.size(); ++i) out.tet_piece[tets[i].index()] = final_id[provisional[i]];
  return out;
}

}  // namespace mtcut::app::view
