#include "cut/mt/fragment_decomposition.h"

#include <cassert>
#include <numeric>
#include <span>

namespace mtcut::cut {
namespace {

std::int32_t find_root(std::int32_t* parent, std::int32_t x) {
  while (parent[x] != x) {
    const std::int32_t up = parent[parent[x]];
    parent[x] = up;
    x = up;
  }
  return x;
}

}  // namespace

Decomposition decompose_fragment(Mt& mt, FragId f, DecompositionScratch& s) {
  assert(f != mt.root() && f != mt.drain());
  Decomposition out;
  const auto created = mt.created(f);
  const auto replaced = mt.replaced(f);
  const std::size_t n_created = created.size();
  const std::size_t n = n_created + replaced.size();
  if (n_created == 0) return out;

  // Union-find through shared vertices; `root` follows tet i's root as it
  // joins earlier tets (their roots are all below i). A vertex's owner is
  // moved to its root once found: most vertices are met again by a tet of
  // the same group, which then needs one look-up, not a walk (this halves
  // the pass on Table 1's largest cut).
  if (s.vertex_owner.size() < mt.num_vertices()) s.vertex_owner.resize(mt.num_vertices(), -1);
  s.parent.resize(n);
  std::iota(s.parent.begin(), s.parent.end(), 0);
  if (s.touched.size() < 4 * n) s.touched.resize(4 * n);  // at most four new vertices per tet
  std::int32_t* const owner_of = s.vertex_owner.data();
  std::int32_t* const parent = s.parent.data();
  engine::VertId* touched = s.touched.data();
  std::size_t components = n;  // less one per union
  // The tets' vertex records are scattered over the MT's arrays; the pass
  // waits on them (and mispredicts its branches), so the record kAhead
  // tets on is fetched early: Table 1's row 5, DAG update 1.20-1.24 ->
  // 1.18-1.21 ms (bench, three alternated runs each).
  constexpr std::size_t kAhead = 8;
  const auto join = [&](std::span<const TetId> tets, std::size_t first) {
    for (std::size_t k = 0; k < tets.size(); ++k) {
      if (k + kAhead < tets.size()) __builtin_prefetch(&mt.tet(tets[k + kAhead]));
      const auto i = static_cast<std::int32_t>(first + k);
      std::int32_t root = i;
      for (engine::VertId v : mt.tet(tets[k])) {
        std::int32_t& owner = owner_of[v.index()];
        if (owner < 0) {
          owner = i;
          *touched++ = v;
          continue;
        }
        if (parent[owner] == root) continue;
        const std::int32_t a = find_root(parent, owner);
        owner = a;
        if (a == root) continue;
        parent[std::max(a, root)] = std::min(a, root);
        root = std::min(a, root);
        --components;
      }
    }
  };
  join(created, 0);
  join(replaced, n_created);
  for (const engine::VertId* v = s.touched.data(); v != touched; ++v) owner_of[v->index()] = -1;
  if (components == 1) return out;  // connected: the common case, no grouping pass

  // Groups numbered by their first tet (a created one); count both kinds.
  s.group.assign(n, -1);
  s.created_count.clear();
  s.replaced_count.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const auto r = static_cast<std::size_t>(find_root(s.parent.data(), static_cast<std::int32_t>(i)));
    if (s.group[r] < 0) {
      s.group[r] = static_cast<std::int32_t>(s.created_count.size());
      s.created_count.push_back(0);
      s.replaced_count.push_back(0);
    }
    const auto g = static_cast<std::size_t>(s.group[r]);
    s.group[i] = static_cast<std::int32_t>(g);  // i's own slot is no longer read as a root's
    (i < n_created ? s.created_count : s.replaced_count)[g] += 1;
  }
  const std::size_t k = s.created_count.size();
  if (k == 1) return out;
  for (std::size_t g = 0; g < k; ++g)
    if (s.created_count[g] == 0 || s.replaced_count[g] == 0) {
      out.outcome = DecomposeOutcome::kKeptWhole;
      return out;
    }

  out.outcome = DecomposeOutcome::kSplit;
  out.parts.push_back(f);
  for (std::size_t g = 1; g < k; ++g) {
    out.parts.push_back(mt.add_fragment());
    mt.reserve_fragment(out.parts[g], static_cast<std::size_t>(s.created_count[g]),
                        static_cast<std::size_t>(s.replaced_count[g]));
  }
  mt.move_groups(f, out.parts, std::span<const std::int32_t>(s.group.data(), n));
  return out;
}

}  // namespace mtcut::cut
