#pragma once
// Generating one split recipe by its scheme's rule (split_lut.h or
// split_bielser17.h), oriented by a reference realisation. The split table
// (split_table.h) holds the results; the LUT's are generated once, when
// mtcut is built (baked_lut.h), since a rule's search costs about 0.2 ms
// per configuration.
//
// Why orient by a reference realisation. A generated tet is a set of four
// labels; its orientation is the sign of a determinant that, for every tet
// the rules make, does not depend on where exactly the cut points sit on
// their edges and faces (tests check this over random placements). So one
// fixed, generic placement of the points of the configuration decides it
// once, and the entry holds positively oriented tets: no permutation or
// parity bookkeeping at run time ("orientation under symmetry").

#include <cstdint>
#include <optional>
#include <string_view>

#include "cut/lut/cut_trace.h"

namespace mtcut::cut {

enum class SplitScheme : std::uint8_t { kLut, kBielser17 };
const char* scheme_name(SplitScheme scheme);                      // "lut", "bielser17"
std::optional<SplitScheme> parse_scheme(std::string_view name);  // inverse of scheme_name

// The tets of a recipe turned positive in the reference realisation. Throws
// std::logic_error when a tet is flat or the volumes do not add up to the tet.
void orient_recipe(const TetConfig& config, const CutTrace& trace, SplitRecipe& recipe);

// Generates the oriented recipe of `config` (must be cut).
SplitRecipe make_recipe(const TetConfig& config, SplitScheme scheme);

}  // namespace mtcut::cut
