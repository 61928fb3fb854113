#pragma once
// The lookup table of splits: configuration key -> tets over local labels,
// oriented. Entries are generated on first use by the scheme's rule
// (split_lut.h or split_bielser17.h) and kept, so after warm-up a split
// costs one array lookup, as the paper's LUT.
//
// Why orient by a reference realisation. A generated tet is a set of four
// labels; its orientation is the sign of a determinant that, for every tet
// the rules make, does not depend on where exactly the cut points sit on
// their edges and faces (tests check this over random placements). So one
// fixed, generic placement of the points of the configuration decides it
// once, and the entry holds positively oriented tets: no permutation or
// parity bookkeeping at run time ("orientation under symmetry").

#include <array>
#include <cstdint>
#include <deque>
#include <optional>
#include <string_view>
#include <vector>

#include "cut/cut_trace.h"

namespace mtcut::cut {

enum class SplitScheme : std::uint8_t { kLut, kBielser17 };
const char* scheme_name(SplitScheme scheme);                      // "lut", "bielser17"
std::optional<SplitScheme> parse_scheme(std::string_view name);  // inverse of scheme_name

// The tets of a recipe turned positive in the reference realisation. Throws
// std::logic_error when a tet is flat or the volumes do not add up to the tet.
void orient_recipe(const TetConfig& config, const CutTrace& trace, SplitRecipe& recipe);

// Generates the oriented recipe of `config` (must be cut).
SplitRecipe make_recipe(const TetConfig& config, SplitScheme scheme);

// A handle on the process-wide table of one scheme: recipes are generated
// once per process whatever the number of tables (generation costs about
// 0.1 ms per configuration, a split then costs one lookup). Thread-safe;
// returned references stay valid for the life of the process.
class SplitTable {
 public:
  explicit SplitTable(SplitScheme scheme = SplitScheme::kLut);

  const SplitRecipe& recipe(const TetConfig& config);
  SplitScheme scheme() const { return scheme_; }
  // Configurations generated so far in this process, for this scheme.
  std::size_t generated() const;

 private:
  struct Store;
  SplitScheme scheme_;
  Store* store_;
};

}  // namespace mtcut::cut
