#include "cut/mt/fragment_decomposition.h"

#include <cassert>
#include <numeric>

namespace mtcut::cut {
namespace {

std::int32_t find_root(std::vector<std::int32_t>& parent, std::int32_t x) {
  while (parent[static_cast<std::size_t>(x)] != x) {
    const std::int32_t up = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
    parent[static_cast<std::size_t>(x)] = up;
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
  s.tets.assign(created.begin(), created.end());
  s.tets.insert(s.tets.end(), replaced.begin(), replaced.end());
  const std::size_t n = s.tets.size();
  if (n_created == 0) return out;

  // Union-find through shared vertices.
  if (s.vertex_owner.size() < mt.num_vertices()) s.vertex_owner.resize(mt.num_vertices(), -1);
  s.parent.resize(n);
  std::iota(s.parent.begin(), s.parent.end(), 0);
  s.touched.clear();
  for (std::size_t i = 0; i < n; ++i) {
    for (engine::VertId v : mt.tet(s.tets[i])) {
      std::int32_t& owner = s.vertex_owner[v.index()];
      if (owner < 0) {
        owner = static_cast<std::int32_t>(i);
        s.touched.push_back(v);
        continue;
      }
      const std::int32_t a = find_root(s.parent, owner), b = find_root(s.parent, static_cast<std::int32_t>(i));
      if (a != b) s.parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
    }
  }
  for (engine::VertId v : s.touched) s.vertex_owner[v.index()] = -1;

  // Groups numbered by their first created tet; count both kinds per group.
  s.group.assign(n, -1);
  std::vector<std::int32_t> created_count, replaced_count;
  for (std::size_t i = 0; i < n; ++i) {
    const auto r = static_cast<std::size_t>(find_root(s.parent, static_cast<std::int32_t>(i)));
    if (s.group[r] < 0) {
      s.group[r] = static_cast<std::int32_t>(created_count.size());
      created_count.push_back(0);
      replaced_count.push_back(0);
    }
    const auto g = static_cast<std::size_t>(s.group[r]);
    (i < n_created ? created_count : replaced_count)[g] += 1;
  }
  const std::size_t k = created_count.size();
  if (k == 1) return out;
  for (std::size_t g = 0; g < k; ++g)
    if (created_count[g] == 0 || replaced_count[g] == 0) {
      out.outcome = DecomposeOutcome::kKeptWhole;
      return out;
    }

  out.outcome = DecomposeOutcome::kSplit;
  out.parts.push_back(f);
  for (std::size_t g = 1; g < k; ++g) out.parts.push_back(mt.add_fragment());
  for (std::size_t i = 0; i < n; ++i) {
    const auto g = static_cast<std::size_t>(s.group[static_cast<std::size_t>(find_root(s.parent, static_cast<std::int32_t>(i)))]);
    if (g == 0) continue;
    if (i < n_created)
      mt.set_birth(s.tets[i], out.parts[g]);
    else
      mt.set_death(s.tets[i], out.parts[g]);
  }
  return out;
}

}  // namespace mtcut::cut
