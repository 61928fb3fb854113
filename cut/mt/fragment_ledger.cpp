#include "cut/mt/fragment_ledger.h"

#include <algorithm>
#include <cassert>
#include <string>
#include <utility>

#include "engine/tet_adjacency.h"

namespace mtcut::cut {
namespace {

using Key = std::array<std::int32_t, 4>;
using Sums = absl::flat_hash_map<Key, int>;

// Adds the tet's unmasked faces, each with its orientation's sign times
// `sign`, to the chains of the fragments `sides` names (+1: the fragment
// creates the tet, -1: replaces it), the root, the drain and `skip` left out.
void add_faces(Sums& sums, const Mt& mt, const engine::Tet& v, engine::FaceMask mask,
               std::span<const std::pair<FragId, int>> sides, int sign, std::span<const FragId> skip) {
  for (int f = 0; f < 4; ++f) {
    if (mask & (1u << f)) continue;
    const std::array<engine::VertId, 3> outward = engine::face_vertices(v, f);
    Key key{0, outward[0].value, outward[1].value, outward[2].value};
    int parity = 1;  // the orientation's sign: the parity of the sort
    for (int i = 1; i < 4; ++i)
      for (int j = 1; j < 4 - i; ++j)
        if (key[j] > key[j + 1]) {
          std::swap(key[j], key[j + 1]);
          parity = -parity;
        }
    for (const auto& [fragment, side] : sides)
      if (fragment.valid() && fragment != mt.root() && fragment != mt.drain() &&
          !std::binary_search(skip.begin(), skip.end(), fragment)) {
        key[0] = fragment.value;
        sums[key] += sign * side * parity;
      }
  }
}

// What `cut` changed, per fragment: the pieces' faces minus the killed
// tets', created side minus replaced side.
void add_cut(Sums& sums, const Mt& mt, const MtChangeReport& cut, std::span<const FragId> skip) {
  sums.reserve(sums.size() + 16 * cut.replaced.size());
  for (const TetReplacement& r : cut.replaced) {
    // A killed tet's fragments are the replacement's; its pieces were born
    // and died in the same ones (only a decomposition, skipped, moves them).
    const std::array<std::pair<FragId, int>, 2> sides{{{r.birth, 1}, {r.death, -1}}};
    add_faces(sums, mt, mt.tet(r.old), mt.boundary_mask(r.old), sides, -1, skip);
    for (std::uint32_t i = r.first; i < r.first + r.count; ++i) {
      const TetId t = cut.made_tets[i];
      add_faces(sums, mt, mt.tet(t), mt.boundary_mask(t), sides, 1, skip);
    }
  }
}

// What f's tets sum to: its created tets' faces minus its replaced tets'.
void add_whole(Sums& sums, const Mt& mt, FragId f) {
  const std::array<std::pair<FragId, int>, 1> created{{{f, 1}}}, replaced{{{f, -1}}};
  for (TetId t : mt.created(f)) add_faces(sums, mt, mt.tet(t), mt.boundary_mask(t), created, 1, {});
  for (TetId t : mt.replaced(f)) add_faces(sums, mt, mt.tet(t), mt.boundary_mask(t), replaced, 1, {});
}

void drop_zeros(Sums& sums) {
  for (auto it = sums.begin(); it != sums.end();) {
    if (it->second == 0)
      sums.erase(it++);
    else
      ++it;
  }
}

}  // namespace

std::vector<FragId> decomposed_fragments(const MtChangeReport& cut) {
  std::vector<FragId> out;
  for (const FragmentSplit& s : cut.fragment_splits) {
    out.push_back(s.old);
    out.insert(out.end(), s.parts.begin(), s.parts.end());
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<FragId> fragments_out_of_balance(const Mt& mt, const MtChangeReport& cut) {
  return FragmentLedger().unbalanced_with(mt, cut, decomposed_fragments(cut));
}

void FragmentLedger::add(const Mt& mt, const MtChangeReport& cut, const MtChangeReport* held) {
  add_cut(sums_, mt, cut, {});
  if (!cut.fragment_splits.empty()) {
    // A decomposed fragment's parts (and a part split again) form a group.
    // Each face lies in one part's region (parts share no vertex), so the
    // group's entries summed face by face are each part's: when they all
    // cancel, every part balances and the group leaves the ledger; else its
    // fragments enter by what their tets sum to (a pass over them).
    absl::flat_hash_map<std::int32_t, std::int32_t> group;  // fragment -> its group's first fragment
    const auto find = [&](std::int32_t f) {
      while (true) {
        const auto it = group.find(f);
        if (it == group.end() || it->second == f) return f;
        f = it->second;
      }
    };
    for (const FragmentSplit& split : cut.fragment_splits) {
      const std::int32_t root = find(split.old.value);
      group[root] = root;
      for (FragId part : split.parts) group[find(part.value)] = root;
    }
    Sums totals;
    for (const auto& [key, sum] : sums_)
      if (group.contains(key[0])) totals[{find(key[0]), key[1], key[2], key[3]}] += sum;
    absl::flat_hash_map<std::int32_t, bool> unbalanced;  // group -> some face does not cancel
    for (const auto& [key, sum] : totals) unbalanced[key[0]] = unbalanced[key[0]] || sum != 0;
    for (auto it = sums_.begin(); it != sums_.end();) {
      if (group.contains(it->first[0]))
        sums_.erase(it++);
      else
        ++it;
    }
    std::vector<FragId> whole;
    for (const auto& [f, root] : group) {
      const auto it = unbalanced.find(find(f));
      if (it != unbalanced.end() && it->second && FragId(f) != mt.root() && FragId(f) != mt.drain())
        whole.emplace_back(f);
    }
    std::sort(whole.begin(), whole.end());
    enter_whole(mt, whole, held);
  }
  drop_zeros(sums_);
}

void FragmentLedger::enter_whole(const Mt& mt, std::span<const FragId> fragments, const MtChangeReport* held) {
  for (FragId f : fragments) add_whole(sums_, mt, f);
  if (held) {  // the held splits in those fragments, taken out of their sums
    const auto in_whole = [&](FragId f) { return std::binary_search(fragments.begin(), fragments.end(), f); };
    for (const TetReplacement& r : held->replaced) {
      std::array<std::pair<FragId, int>, 2> sides{{{FragId(), 1}, {FragId(), -1}}};
      if (in_whole(r.birth)) sides[0].first = r.birth;
      if (in_whole(r.death)) sides[1].first = r.death;
      if (!sides[0].first.valid() && !sides[1].first.valid()) continue;
      add_faces(sums_, mt, mt.tet(r.old), mt.boundary_mask(r.old), sides, 1, {});
      for (std::uint32_t i = r.first; i < r.first + r.count; ++i) {
        const TetId t = held->made_tets[i];
        add_faces(sums_, mt, mt.tet(t), mt.boundary_mask(t), sides, -1, {});
      }
    }
  }
  drop_zeros(sums_);
}

void FragmentLedger::subtract(const Mt& mt, const MtChangeReport& changes, std::span<const std::uint8_t> which) {
  assert(which.size() == changes.replaced.size());
  for (std::size_t k = 0; k < changes.replaced.size(); ++k) {
    if (!which[k]) continue;
    const TetReplacement& r = changes.replaced[k];
    const std::array<std::pair<FragId, int>, 2> sides{{{r.birth, 1}, {r.death, -1}}};
    add_faces(sums_, mt, mt.tet(r.old), mt.boundary_mask(r.old), sides, 1, {});
    for (std::uint32_t i = r.first; i < r.first + r.count; ++i) {
      const TetId t = changes.made_tets[i];
      add_faces(sums_, mt, mt.tet(t), mt.boundary_mask(t), sides, -1, {});
    }
  }
  drop_zeros(sums_);
}

std::vector<FragId> FragmentLedger::unbalanced_with(const Mt& mt, const MtChangeReport& cut,
                                                    std::span<const FragId> skip) const {
  Sums sums;
  add_cut(sums, mt, cut, skip);
  std::vector<FragId> out;
  for (const auto& [key, sum] : sums) {
    const auto owed = sums_.find(key);
    if (sum + (owed == sums_.end() ? 0 : owed->second) != 0) out.emplace_back(key[0]);
  }
  for (const auto& [key, owed] : sums_)
    if (!sums.contains(key) && !std::binary_search(skip.begin(), skip.end(), FragId(key[0])))
      out.emplace_back(key[0]);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

bool FragmentLedger::owes(FragId f) const {
  return std::any_of(sums_.begin(), sums_.end(), [&](const auto& entry) { return entry.first[0] == f.value; });
}

void FragmentLedger::renumber(const Mt::Compaction& compaction) {
  Sums sums;
  sums.reserve(sums_.size());
  for (const auto& [old_key, sum] : sums_) {
    Key key = old_key;
    for (int i = 1; i < 4; ++i) {
      key[i] = compaction.vertex_map[static_cast<std::size_t>(key[i])];
      assert(key[i] >= 0 && "Mt::compact dropped a vertex of a face the ledger holds");
    }
    sums.emplace(key, sum);
  }
  sums_ = std::move(sums);
}

engine::ValidationReport FragmentLedger::validate(const Mt& mt, const MtChangeReport* since) const {
  engine::ValidationReport report;
  const std::vector<FragId> decomposed = since ? decomposed_fragments(*since) : std::vector<FragId>{};
  std::vector<FragId> named;
  for (const auto& [key, sum] : sums_) {
    if (sum == 0) report.add("fragment ledger: a zero entry");
    if (key[0] < 0 || static_cast<std::size_t>(key[0]) >= mt.num_fragments()) {
      report.add("fragment ledger: fragment " + std::to_string(key[0]) + " is not in the MT");
      return report;
    }
    for (int i = 1; i < 4; ++i)
      if (key[i] < 0 || static_cast<std::size_t>(key[i]) >= mt.num_vertices()) {
        report.add("fragment ledger: a face of vertex " + std::to_string(key[i]) + ", not in the MT");
        return report;
      }
    if (!std::binary_search(decomposed.begin(), decomposed.end(), FragId(key[0]))) named.emplace_back(key[0]);
  }
  std::sort(named.begin(), named.end());
  named.erase(std::unique(named.begin(), named.end()), named.end());
  Sums expected;
  for (const auto& [key, sum] : sums_)
    if (std::binary_search(named.begin(), named.end(), FragId(key[0]))) expected[key] += sum;
  if (since) {
    Sums more;
    add_cut(more, mt, *since, decomposed);
    for (const auto& [key, sum] : more)
      if (std::binary_search(named.begin(), named.end(), FragId(key[0]))) expected[key] += sum;
  }
  Sums actual;
  for (FragId f : named) add_whole(actual, mt, f);
  drop_zeros(expected);
  drop_zeros(actual);
  for (FragId f : named) {
    bool same = true;
    for (const auto& [key, sum] : actual)
      if (key[0] == f.value) {
        const auto it = expected.find(key);
        same = same && it != expected.end() && it->second == sum;
      }
    for (const auto& [key, sum] : expected)
      if (key[0] == f.value) same = same && actual.contains(key);
    if (!same)
      report.add("fragment ledger: fragment " + std::to_string(f.value) +
                 " is out of balance by other faces than the ledger holds");
  }
  return report;
}

}  // namespace mtcut::cut
