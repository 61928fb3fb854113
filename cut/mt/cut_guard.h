#pragma once
// A finished cut checked where it can have broken the MT, before it is kept.
//
// Why. One planar cut of the MT is conforming by construction (mt_cut.h).
// A cut that meets an earlier crack is not always: where a stroke's next
// straight part crosses the front its last part left with the blade's tip
// inside the tissue, the new crack can reach an edge of the old one, and
// the tissue around that edge is then two wedges joined only along it (a
// boundary edge of four faces). The single-resolution cutter splits such
// vertices (cut/vertex_unpinch.h); the MT cut does not, so the cutter keeps
// a cut only when it finds no such pinch and no flat piece, and otherwise
// takes it back (cut_retraction.h): the incision stays as it was, which the
// paper's relaxed correctness allows, and the MT stays valid.
//
// What is checked: fragments still replace a region by the same region
// (engine validate_fragment: where the new crack meets an old one the cut
// may bend differently in a fragment's two tessellations; a random stroke
// of two legs through a cylinder did so). Each fragment the cut changed
// and did not decompose is checked from what the cut changed in it, with
// what the part's commits owe it (fragment_ledger.h: every fragment was
// valid before the part's first cut; a part's commit leaves the fragments
// owing what its front splits, and the front's check pays it back; a
// part that has met no older crack is not checked so, part_record.h); the
// fragments where the new crack meets an old one (they hold a piece of an
// earlier cut that this one split or relabelled), and those that owe the
// part's ledger, are checked whole, with their parts, when the cut
// decomposed them;
// and at the finest and coarsest resolutions (those validate() checks
// whole): every piece the cut made is positively oriented (exact),
// and around every edge of a piece whose two ends cuts made, the faces
// shared by no other tet are none or two: for the pieces of a tet that was
// itself a piece of an earlier cut (where the new crack meets an old one),
// every such edge; elsewhere, those whose two ends earlier cuts made. The
// other edges and fragments are a single planar cut's through tets no cut
// had touched, conforming by construction. Around those same edges, at
// every resolution: the tets one fragment creates hold none or two of the
// surface's faces through the edge, summed (more, and every frontier that
// shows the fragment, as a mixed-resolution one can, is pinched there).
// The edge check costs an index query per group of neighbouring edge
// ends that earlier cuts made, only near old cracks;
// the fragment check the tets the cut changed, and a pass over the tets of
// the fragments checked whole.

#include <cstddef>
#include <vector>

#include "cut/mt/fragment_ledger.h"
#include "cut/mt/mt_change_report.h"
#include "cut/mt/part_record.h"
#include "engine/mt/mt.h"
#include "engine/mt/tet_bvh.h"
#include "engine/validation.h"

namespace mtcut::cut {

// A part's commit of the frame whose front is checked: the edges of its
// pieces are checked with the front's (check_cut), as it is kept before
// them with only its pieces' orientation checked.
struct FrameCommit {
  const MtChangeReport* changes = nullptr;
  std::size_t first_new_vertex = 0;  // its own vertices from here on
};

// The ledger a cut of `part` (none: not a part's) is checked against, its
// fragments' balance with it (fragment_ledger.h): nothing owed for a cut
// that is not a part's or for a part that has committed nothing yet, the
// part's ledger once it has met an older crack, else none (nullptr: no
// balance check; a part's cuts through tets no cut had touched conform by
// construction). A check against a ledger sums the part's whole front.
const FragmentLedger* ledger_checked(const PartRecord* part);

// `cut`: everything the finished cut changed; vertices from `first_cut_vertex`
// on were made by cuts (earlier ones and this), the cut's own from
// `first_new_vertex` on. `part`: the cut is a frame of a stroke's part cut
// progressively (part_record.h), whose committed points are of the same
// planar crack as this cut's, not an earlier crack, and whose commits owe
// the fragments what the ledger holds; `select`: which of the part's cuts
// (a commit's fragments and edges are checked by the front after it, given
// `commit`). `kept`: a front's splits kept from earlier frames (the
// part's, held in its record), checked when they were made; they join the
// cut where the fragments' balance is checked, which sums the whole front.
// Their edges are not checked again on their own: a tet around one that
// changed since is a piece of this cut or of `commit` with that edge, and
// such a piece checks an edge it shares with a kept piece of an earlier
// cut's piece as that piece's own check did. `taken`: the part's front
// and its ledger balanced before the frame (the last front's check
// passed), `commit` decomposed no fragment, and `taken` holds, negated,
// the chain of the splits the frame took back of that front
// (FragmentLedger::subtract): the balance is then the same sum taken by
// what the frame changed, its commit, `taken` and the cut, not by the
// whole front with the ledger. Empty when the cut may be kept.
engine::ValidationReport check_cut(const engine::Mt& mt, const engine::TetBvh& bvh, const MtChangeReport& cut,
                                   std::size_t first_cut_vertex, std::size_t first_new_vertex,
                                   const PartRecord* part, CutSelect select, const FrameCommit* commit = nullptr,
                                   const MtChangeReport* kept = nullptr, const FragmentLedger* taken = nullptr);

}  // namespace mtcut::cut
