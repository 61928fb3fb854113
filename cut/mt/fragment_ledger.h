#pragma once
// What a cut changed in each fragment's two tessellations, as face chains,
// and what a stroke's part owes the fragments between its frames.
//
// Why chains. A fragment is valid when the tets it creates and those it
// replaces fill the same region (engine validate_fragment): the inner faces
// (not on the object's surface) of the two tessellations are the same
// oriented faces. As a chain, the inner faces of a tet set are the sum of
// its tets' unmasked oriented faces (a face two tets share cancels), which
// is linear in the tets. So a fragment valid before a cut stays valid
// exactly when, summed over the cut's replacements in it, the pieces' faces
// minus the killed tets' are the same on its created side as on its
// replaced side; that costs the tets the cut changed, where
// validate_fragment costs the fragment's (80,000 tets, 60 ms, for the
// fragments a turning stroke's junction touches in the liver).
//
// Why a ledger. A part's commits (part_record.h) split the finer tets of a
// fragment that its polygon crosses completely, and only its front, or its
// end, the coarser ones the polygon's outline passes through: between the
// two a fragment is out of balance by the chain the commits left. The
// ledger holds that chain per fragment; the front and the end are checked
// to pay it back exactly (the fragments they change balance with it), so a
// part may commit where it meets an older crack, whose fragments would
// otherwise have to be checked whole every frame.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "absl/container/flat_hash_map.h"
#include "cut/mt/mt_change_report.h"
#include "engine/mt/mt.h"
#include "engine/validation.h"

namespace mtcut::cut {

using engine::FragId;
using engine::Mt;

// The fragments a cut decomposed, and their parts (sorted).
std::vector<FragId> decomposed_fragments(const MtChangeReport& cut);

// The fragments (not the root or the drain, none the cut decomposed;
// sorted) whose two tessellations the cut changed unequally.
std::vector<FragId> fragments_out_of_balance(const Mt& mt, const MtChangeReport& cut);

class FragmentLedger {
 public:
  // Adds what `cut` changed in its fragments (not the root or the drain).
  // A fragment the cut decomposed, and its parts, leave the ledger when
  // they balance; else they are entered by what their tets sum to (a pass
  // over their tets, as the decomposition was).
  // `held`: a part's front the cut ran beside (provisional splits kept in
  // the MT, their replacements naming the fragments their pieces are in
  // now): a fragment entered by what its tets sum to is entered as if they
  // were whole, so that the ledger stays what the commits owe.
  void add(const Mt& mt, const MtChangeReport& cut, const MtChangeReport* held = nullptr);
  // Enters `fragments` (sorted, unique, none in the ledger) by what their
  // tets sum to, `held`'s splits taken out (as add() does): a pass over
  // their tets. The fragments a part's commits changed, entered so when it
  // meets an older crack, owe what add() would have summed commit by commit
  // (each balanced before the part; PartRecord::meet_old_crack).
  void enter_whole(const Mt& mt, std::span<const FragId> fragments, const MtChangeReport* held);

  // Takes out what the replacements of `changes` flagged in `which` (one
  // flag per replacement) changed in their fragments: their chain, as add()
  // sums it, negated. A part's front split again takes its splits out so
  // (TimeCriticalCutter::keep_front).
  void subtract(const Mt& mt, const MtChangeReport& changes, std::span<const std::uint8_t> which);

  // The fragments (not the root, the drain or in `skip`, which is sorted)
  // that stay out of balance once `cut` is added, sorted. With an empty
  // ledger: those whose two tessellations `cut` changed unequally.
  std::vector<FragId> unbalanced_with(const Mt& mt, const MtChangeReport& cut, std::span<const FragId> skip) const;

  bool empty() const { return sums_.empty(); }
  friend bool operator==(const FragmentLedger& a, const FragmentLedger& b) { return a.sums_ == b.sums_; }
  bool owes(FragId f) const;  // the ledger has entries for f
  std::size_t size() const { return sums_.size(); }  // (fragment, face) entries
  // The MT was compacted (Mt::compact keeps the vertices' order, so a
  // face's sorted ids stay sorted).
  void renumber(const Mt::Compaction& compaction);

  // Every fragment the ledger names is out of balance by exactly its
  // entries, once `since` (changes made after the ledger's last add, such
  // as the part's held front; may be null) is added: a pass over those
  // fragments' tets.
  engine::ValidationReport validate(const Mt& mt, const MtChangeReport* since) const;

 private:
  // (fragment, the face's ascending vertex ids) -> coefficient; no zeros.
  using Sums = absl::flat_hash_map<std::array<std::int32_t, 4>, int>;
  Sums sums_;
};

}  // namespace mtcut::cut
