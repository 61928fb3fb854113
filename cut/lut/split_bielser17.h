#pragma once
// The reference split of Bielser et al. (the paper's figure 4, "1:17"),
// kept only to compare element counts and timings with the LUT.
//
// Why this form. Bielser's scheme pre-splits every cut tet with one generic
// pattern, whatever the cut: a node on each cut edge (one per side), a node
// on each face the cut runs across, and interior sub-tets joining them; the
// paper counts 17 tets per split tet. The figure is lost from our copy of
// the paper, and a literal 14-node pattern would leave nodes on edges and
// faces that uncut neighbours do not share. So the reference keeps the
// generic idea within a conforming mesh: every face the cut crosses gets a
// node (split in two where the cut runs through the face, the LUT's face
// point where the cut ends in it), the tet gets a centre node on the cut
// (split in two when the cut goes right through), and every boundary
// triangle is coned to the centre. No case analysis, no optimisation:
// A 16, B 20, C 10, D 14, E 18, O 16 tets.

#include "cut/lut/cut_trace.h"

namespace mtcut::cut {

// Tets of the 1:17 reference split of `config` (must be cut), not yet oriented.
SplitRecipe generate_bielser17_split(const TetConfig& config);

}  // namespace mtcut::cut
