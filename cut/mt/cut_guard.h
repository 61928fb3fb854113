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
// of two legs through a cylinder did so). When every fragment was valid
// before the cut, each fragment it changed and did not decompose is checked
// from what the cut changed in it (fragments_out_of_balance); the
// fragments where the new crack meets an old one (they hold a piece of an
// earlier cut that this one split or relabelled) are checked whole, with
// their parts, when the cut decomposed them or when not every fragment was
// valid before it (around a part's commits, part_record.h);
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
// The edge check costs a point query per edge end, only near old cracks;
// the fragment check the tets the cut changed, and a pass over the tets of
// the fragments checked whole.

#include <cstddef>
#include <vector>

#include "cut/mt/mt_change_report.h"
#include "cut/mt/part_record.h"
#include "engine/mt/mt.h"
#include "engine/mt/tet_bvh.h"
#include "engine/validation.h"

namespace mtcut::cut {

// The fragments a cut decomposed, and their parts (sorted).
std::vector<engine::FragId> decomposed_fragments(const MtChangeReport& cut);

// The fragments (not root or drain, none the cut decomposed; sorted) whose
// two tessellations the cut changed unequally. A fragment is valid when the
// inner faces (not on the object's boundary) of the tets it creates and of
// those it replaces are the same oriented faces (engine validate_fragment).
// As a chain, the inner faces of a valid tet set are the sum of its tets'
// unmasked oriented faces (a face two tets share cancels), which is linear
// in the tets: a fragment valid before the cut stays valid exactly when,
// summed over the cut's replacements in it, the pieces' faces minus the
// killed tet's are the same on its created side as on its replaced side.
// That costs the tets the cut changed, where validate_fragment costs the
// fragment's (80,000 tets, 60 ms, for the fragments a turning stroke's
// junction touches in the liver). Its volume check needs nothing more: a
// split or relabel keeps its tet's volume.
std::vector<engine::FragId> fragments_out_of_balance(const engine::Mt& mt, const MtChangeReport& cut);

// `cut`: everything the finished cut changed; vertices from `first_cut_vertex`
// on were made by cuts (earlier ones and this), the cut's own from
// `first_new_vertex` on. `part`: the cut is a frame of a stroke's part cut
// progressively (part_record.h), whose committed points are of the same
// planar crack as this cut's, not an earlier crack. `fragments_valid`:
// every fragment was valid when the cut started and must be when it ends
// (not so around a part's commits: part_record.h), so the fragments it
// changed are checked by what it changed (fragments_out_of_balance). Empty
// when the cut may be kept.
engine::ValidationReport check_cut(const engine::Mt& mt, const engine::TetBvh& bvh, const MtChangeReport& cut,
                                   std::size_t first_cut_vertex, std::size_t first_new_vertex,
                                   const PartRecord* part, bool fragments_valid);

}  // namespace mtcut::cut
