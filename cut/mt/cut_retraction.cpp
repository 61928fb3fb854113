#include "cut/mt/cut_retraction.h"

#include <iterator>
#include <stdexcept>
#include <string>

namespace mtcut::cut {
namespace {

// The fragment f stands for once the cut's parts are merged back: parts
// (from fragments_before on) map to the fragment they were split from,
// following chains (a part split again within the cut).
class PartMap {
 public:
  PartMap(const MtChangeReport& cut, std::size_t fragments_before) : first_(fragments_before) {
    for (const FragmentSplit& s : cut.fragment_splits)
      for (FragId p : s.parts) {
        if (p == s.old) continue;
        if (p.index() < first_) throw std::logic_error("retract_cut: a part made before the cut");
        const std::size_t i = p.index() - first_;
        if (of_.size() <= i) of_.resize(i + 1);
        of_[i] = s.old;
      }
  }
  FragId resolve(FragId f) const {
    while (f.valid() && f.index() >= first_) {
      const std::size_t i = f.index() - first_;
      if (i >= of_.size() || !of_[i].valid()) return FragId();
      f = of_[i];
    }
    return f;
  }

 private:
  std::size_t first_;
  std::vector<FragId> of_;  // (parts) the fragment each part came from, none = not a part
};

}  // namespace

engine::ValidationReport validate_retractable(const engine::Mt& mt, const MtChangeReport& cut,
                                              std::size_t fragments_before) {
  engine::ValidationReport report;
  const PartMap parts(cut, fragments_before);
  for (const TetReplacement& r : cut.replaced) {
    if (mt.alive(r.old)) report.add("retraction: replaced tet " + std::to_string(r.old.value) + " is alive");
    if (!r.birth.valid() || r.birth.index() >= fragments_before)
      report.add("retraction: replaced tet " + std::to_string(r.old.value) + " was born in a fragment the cut made");
    if (r.first + r.count > cut.made_tets.size())
      report.add("retraction: replaced tet " + std::to_string(r.old.value) + " has pieces out of range");
  }
  for (TetId t : cut.made_tets)
    if (!mt.alive(t)) report.add("retraction: piece " + std::to_string(t.value) + " is dead");
  for (std::size_t f = fragments_before; f < mt.num_fragments(); ++f)
    if (!parts.resolve(FragId(f)).valid())
      report.add("retraction: fragment " + std::to_string(f) + " is not a part the cut made");
  return report;
}

CutRetraction retract_cut(engine::Mt& mt, engine::TetBvh& bvh, const MtChangeReport& cut,
                          std::size_t fragments_before, const engine::TetBvh::Mark* bvh_mark) {
  if (const auto report = validate_retractable(mt, cut, fragments_before); !report.ok())
    throw std::logic_error("retract_cut: " + report.problems.front());
  const PartMap parts(cut, fragments_before);
  CutRetraction out;
  // Tets in the parts go back to the fragments the parts were split from.
  // Pieces among them are killed below; the others are the fragments' own.
  for (std::size_t f = mt.num_fragments(); f-- > fragments_before;) {
    const FragId part(f), into = parts.resolve(part);
    out.merged.emplace_back(part, into);
    const std::vector<TetId> created(mt.created(part).begin(), mt.created(part).end());
    for (TetId t : created) mt.set_birth(t, into);
    const std::vector<TetId> replaced(mt.replaced(part).begin(), mt.replaced(part).end());
    for (TetId t : replaced) mt.set_death(t, into);
  }
  out.killed.reserve(cut.made_tets.size());
  for (TetId t : cut.made_tets) {
    if (!bvh_mark) bvh.remove(t);
    mt.kill_tet(t);
    out.killed.push_back(t);
  }
  out.revived.reserve(cut.replaced.size());
  for (auto r = cut.replaced.rbegin(); r != cut.replaced.rend(); ++r) {
    mt.revive_tet(r->old, r->birth, parts.resolve(r->death));
    if (!bvh_mark) bvh.insert(mt, r->old);
    out.revived.push_back(r->old);
  }
  if (bvh_mark) bvh.roll_back(*bvh_mark);
  while (mt.num_fragments() > fragments_before) {
    mt.remove_last_fragment();
    ++out.fragments_removed;
  }
  out.unused = cut.made_vertices;
  return out;
}

void CutRetraction::append(CutRetraction&& later) {
  revived.insert(revived.end(), later.revived.begin(), later.revived.end());
  killed.insert(killed.end(), later.killed.begin(), later.killed.end());
  merged.insert(merged.end(), later.merged.begin(), later.merged.end());
  fragments_removed += later.fragments_removed;
  unused.insert(unused.end(), std::make_move_iterator(later.unused.begin()), std::make_move_iterator(later.unused.end()));
}

CutRetraction retract_replacements(engine::Mt& mt, engine::TetBvh& bvh, MtChangeReport& cut,
                                   std::span<const std::uint8_t> take) {
  if (!cut.fragment_splits.empty()) throw std::logic_error("retract_replacements: the cut decomposed fragments");
  if (take.size() != cut.replaced.size()) throw std::logic_error("retract_replacements: one flag per replacement");
  CutRetraction out;
  MtChangeReport kept;
  kept.made_vertices = std::move(cut.made_vertices);
  for (std::size_t i = 0; i < cut.replaced.size(); ++i) {
    TetReplacement r = cut.replaced[i];
    const std::span<const TetId> pieces(cut.made_tets.data() + r.first, r.count);
    if (!take[i]) {
      r.first = static_cast<std::uint32_t>(kept.made_tets.size());
      kept.made_tets.insert(kept.made_tets.end(), pieces.begin(), pieces.end());
      kept.replaced.push_back(r);
      continue;
    }
    if (mt.alive(r.old) || pieces.empty()) throw std::logic_error("retract_replacements: a replaced tet is alive");
    const FragId birth = mt.birth(pieces.front()), death = mt.death(pieces.front());
    for (TetId t : pieces) {
      if (!mt.alive(t)) throw std::logic_error("retract_replacements: a piece is dead");
      if (mt.birth(t) != birth || mt.death(t) != death)
        throw std::logic_error("retract_replacements: the pieces of one tet are in different fragments");
      bvh.remove(t);
      mt.kill_tet(t);
      out.killed.push_back(t);
    }
    mt.revive_tet(r.old, birth, death);
    bvh.insert(mt, r.old);
    out.revived.push_back(r.old);
  }
  cut = std::move(kept);
  return out;
}

engine::ValidationReport validate_replacements(const engine::Mt& mt, const MtChangeReport& cut) {
  engine::ValidationReport report;
  if (!cut.fragment_splits.empty()) report.add("retraction: a provisional cut decomposed fragments");
  for (const TetReplacement& r : cut.replaced) {
    if (mt.alive(r.old)) report.add("retraction: replaced tet " + std::to_string(r.old.value) + " is alive");
    if (r.count == 0 || r.first + r.count > cut.made_tets.size()) {
      report.add("retraction: replaced tet " + std::to_string(r.old.value) + " has pieces out of range");
      continue;
    }
    const TetId first = cut.made_tets[r.first];
    for (std::uint32_t k = 0; k < r.count; ++k) {
      const TetId t = cut.made_tets[r.first + k];
      if (!mt.alive(t)) report.add("retraction: piece " + std::to_string(t.value) + " is dead");
      else if (mt.alive(first) && (mt.birth(t) != mt.birth(first) || mt.death(t) != mt.death(first)))
        report.add("retraction: the pieces of tet " + std::to_string(r.old.value) + " are in different fragments");
    }
  }
  return report;
}

std::vector<FragId> retract_fragment_set(const engine::Mt& mt, std::span<const FragId> fragments,
                                         const CutRetraction& retraction) {
  const std::size_t n = mt.num_fragments();
  std::vector<FragId> into(n + retraction.fragments_removed);
  for (const auto& [part, whole] : retraction.merged) into[part.index()] = whole;
  std::vector<char> in(n, 0);
  std::vector<FragId> stack;
  const auto add = [&](FragId f) {
    if (!in[f.index()]) {
      in[f.index()] = 1;
      stack.push_back(f);
    }
  };
  for (FragId f : fragments) {
    while (f.index() >= n) f = into[f.index()];
    add(f);
  }
  // Closure under parents: a fragment's parents are the births of the tets
  // it replaces.
  while (!stack.empty()) {
    const FragId f = stack.back();
    stack.pop_back();
    for (TetId t : mt.replaced(f)) add(mt.birth(t));
  }
  std::vector<FragId> out;
  for (std::size_t f = 0; f < n; ++f)
    if (in[f]) out.emplace_back(f);
  return out;
}

void follow_retraction(const engine::Mt& mt, engine::Frontier& frontier, const CutRetraction& retraction) {
  if (retraction.fragments_removed > 0 || !retraction.merged.empty()) {
    frontier = engine::Frontier::from_fragments(mt, retract_fragment_set(mt, frontier.fragments(), retraction));
    return;
  }
  std::vector<TetId> tets(retraction.revived);
  tets.insert(tets.end(), retraction.killed.begin(), retraction.killed.end());
  frontier.follow_edit(mt, {}, tets, {});
}

}  // namespace mtcut::cut
