#include "cut/mt/follow_cut.h"

#include <algorithm>
#include <cstdint>

namespace mtcut::cut {

std::vector<FragId> map_fragment_set(std::span<const FragId> fragments, std::span<const FragmentSplit> splits) {
  std::vector<FragId> out(fragments.begin(), fragments.end());
  std::size_t n = 0;
  for (FragId f : out) n = std::max(n, f.index() + 1);
  for (const FragmentSplit& s : splits)
    for (FragId p : s.parts) n = std::max(n, p.index() + 1);
  std::vector<char> in(n, 0);
  for (FragId f : out) in[f.index()] = 1;
  for (const FragmentSplit& s : splits) {
    if (!in[s.old.index()]) continue;
    for (FragId p : s.parts)
      if (!in[p.index()]) {
        in[p.index()] = 1;
        out.push_back(p);
      }
  }
  std::sort(out.begin(), out.end());
  return out;
}

Frontier map_frontier(const Mt& mt, const Frontier& frontier, std::span<const FragmentSplit> splits) {
  const std::vector<FragId> set = map_fragment_set(frontier.fragments(), splits);
  return Frontier::from_fragments(mt, set);
}

void follow_cut(const Mt& mt, Frontier& frontier, const MtChangeReport& changes) {
  if (changes.empty()) return;
  // mark[f]: 1 f joins S here, 2 f is already listed in `regrouped` (a
  // provisional cut splits no fragment: no marks).
  std::vector<std::uint8_t> mark(changes.fragment_splits.empty() ? 0 : mt.num_fragments(), 0);
  std::vector<FragId> joined, regrouped;
  for (const FragmentSplit& s : changes.fragment_splits) {  // in order: a part may split again
    const bool in_s = frontier.contains(s.old) || (mark[s.old.index()] & 1);
    for (FragId p : s.parts) {
      if (in_s && p != s.old && !(mark[p.index()] & 1)) {
        mark[p.index()] |= 1;
        joined.push_back(p);
      }
      if (p.valid() && !(mark[p.index()] & 2)) {
        mark[p.index()] |= 2;
        regrouped.push_back(p);
      }
    }
  }
  std::vector<TetId> tets;
  tets.reserve(changes.replaced.size() + changes.made_tets.size());
  for (const TetReplacement& r : changes.replaced) tets.push_back(r.old);
  tets.insert(tets.end(), changes.made_tets.begin(), changes.made_tets.end());
  frontier.follow_edit(mt, joined, tets, regrouped);
}

}  // namespace mtcut::cut
