#pragma once
// The World's frontier after a cut of the MT: a fragment set S must follow
// the cut, since every part of a fragment in S that the cut decomposed
// must be in S (otherwise a part's children could be in S without their
// parent), and the frontier's mesh follows the tets the cut killed and made
// (time_critical_cutter.h: the World's step after each run()).

#include <span>
#include <vector>

#include "cut/mt/mt_change_report.h"
#include "engine/mt/frontier.h"
#include "engine/mt/mt.h"

namespace mtcut::cut {

using engine::FragId;
using engine::Frontier;
using engine::Mt;

// S mapped through fragment splits (in order): every part of a fragment in S is in S.
std::vector<FragId> map_fragment_set(std::span<const FragId> fragments, std::span<const FragmentSplit> splits);
// The frontier of the mapped set, rebuilt over the MT as it is now (its
// tets, vertices and visible fragments follow the split tets).
Frontier map_frontier(const Mt& mt, const Frontier& frontier, std::span<const FragmentSplit> splits);
// The same frontier as map_frontier(mt, frontier, changes.fragment_splits),
// reached in place from what `changes` says the cut did (Frontier::follow_edit):
// costs the tets the cut killed and made, not a pass over the MT. What the
// World does after every run().
void follow_cut(const Mt& mt, Frontier& frontier, const MtChangeReport& changes);

}  // namespace mtcut::cut
