#pragma once
// Retracting a provisional cut: the MT as it was before the cut, up to the
// order of the fragments' lists. The tets the cut split are alive again in
// the fragments they had, its pieces are dead, the fragments it decomposed
// are whole again and the parts it made are removed (they were the last
// fragments). This is what makes progressive cutting (DESIGN.md,
// "Progressive cutting") split every tet once from its original: while a
// stroke's straight part grows, each frame cuts the part's front (or, before
// its plane is fixed, its whole polygon so far) provisionally, and the next
// frame retracts that cut (of a front, only the splits the grown polygon
// changes: retract_replacements) and cuts the grown part afresh, so no
// piece of a provisional split is ever cut again (part_record.h).
//
// Why vertices stay. The vertices the cut made are left in the MT, unused,
// and its pieces keep their slots, dead (a tet is never erased, only
// killed): ids are not reused while a stroke goes on, so whatever a caller
// keyed by vertex or tet id (the spring model, a snapshot of the simulated
// state) stays unambiguous. Between strokes the cutter reclaims them
// (TimeCriticalCutter::reclaim, Mt::compact), and the callers renumber.

#include <span>
#include <vector>

#include "cut/mt/mt_change_report.h"
#include "engine/mt/frontier.h"
#include "engine/mt/mt.h"
#include "engine/mt/tet_bvh.h"
#include "engine/validation.h"

namespace mtcut::cut {

struct CutRetraction {
  std::vector<TetId> revived;  // the tets the cut had split or relabelled, alive again
  std::vector<TetId> killed;   // its pieces that were alive (now dead)
  // (part, fragment): each fragment the cut had made, removed, and the one
  // it was a part of (whose id survives).
  std::vector<std::pair<FragId, FragId>> merged;
  std::size_t fragments_removed = 0;
  // The vertices the cut made that none of its pieces left uses (a point a
  // later cut took too, such as a part's commit, is still used by that
  // cut's pieces: the time-critical cutter drops those from the list).
  std::vector<MadeVertex> unused;

  // Adds what a later retraction took back (a cut taken back after this one).
  void append(CutRetraction&& later);
};

// Undoes `cut`, every change a provisional cut made (all its calls' reports
// appended, cut/mt/mt_change_report.h), started when the MT had
// `fragments_before` fragments and followed by no other edit of the MT.
// `bvh` follows: rolled back to `bvh_mark` (taken when the cut started,
// with nothing but the cut editing the index since) when given, else edited
// tet by tet. Throws std::logic_error when the report does not match the MT
// (a piece already killed by something else, a part that still holds tets).
CutRetraction retract_cut(engine::Mt& mt, engine::TetBvh& bvh, const MtChangeReport& cut,
                          std::size_t fragments_before, const engine::TetBvh::Mark* bvh_mark = nullptr);

// Takes back the replacements of a provisional cut (one that decomposed
// no fragment) that `take` marks (one entry per cut.replaced), tet by tet,
// and drops them from `cut`, with its processed fragments and counts: what
// is left is what it holds, and every vertex it made (which of them the
// pieces left use is the holder's to say: PartRecord::hold).
// Later cuts may have edited the MT since (a part's commits, which may
// decompose the fragments its pieces are in): each tet revived goes back
// to the fragments its pieces are in now, one birth and one death, as a
// split that does not separate its tet leaves them. Throws
// std::logic_error when the cut decomposed a fragment, a piece is dead, or
// the pieces of one tet are in different fragments.
CutRetraction retract_replacements(engine::Mt& mt, engine::TetBvh& bvh, MtChangeReport& cut,
                                   std::span<const std::uint8_t> take);

// What retract_replacements needs: no fragment decomposed, every replaced
// tet dead, its pieces alive and in one birth and one death fragment.
engine::ValidationReport validate_replacements(const engine::Mt& mt, const MtChangeReport& cut);

// S after a retraction: every removed part replaced by the fragment it was
// a part of, then closed under parents (a part that the level of detail had
// left out may have had parents outside S).
std::vector<FragId> retract_fragment_set(const engine::Mt& mt, std::span<const FragId> fragments,
                                         const CutRetraction& retraction);
// `frontier` follows the retraction: the frontier of that set over the MT
// as it is now. A retraction that merged no fragments kept every
// fragment's region, and the frontier follows it in place
// (Frontier::follow_edit: the tets revived and killed); else it is rebuilt
// from the set.
void follow_retraction(const engine::Mt& mt, engine::Frontier& frontier, const CutRetraction& retraction);

// What the MT must satisfy for `cut` to be retracted: every piece alive or
// killed by nothing else, every replaced tet dead, every fragment from
// `fragments_before` on a part the cut made.
engine::ValidationReport validate_retractable(const engine::Mt& mt, const MtChangeReport& cut,
                                              std::size_t fragments_before);

}  // namespace mtcut::cut
