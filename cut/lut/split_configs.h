#pragma once
// Every configuration a tet can be cut in: what the LUT is generated for
// when mtcut is built (baked_lut.h) and what the split tests walk.
//
// The id order (TetConfig::rank) matters only where a face of the tet is
// split into a triangle and a quad: the quad's diagonal is chosen by global
// vertex id. Elsewhere the split is the same for all 24 orders (a test
// checks it), so such configurations are listed, and looked up, with the
// identity order.

#include <cstdint>
#include <vector>

#include "cut/tet_classifier.h"

namespace mtcut::cut {

// A face of `c` is split into a triangle and a quad (two of its edges are cut).
bool order_matters(const TetConfig& c);

// The key `c` is tabled under: its own, or with the identity order when the
// order does not matter.
std::uint32_t table_key(const TetConfig& c);

// Every configuration that is cut: vertex states, coverage of the straddling
// edges, a bent variant where no vertex is on the cut, and `orders` of the 24
// id orders (all when 24) where the order matters, the identity otherwise.
std::vector<TetConfig> all_cut_configs(int orders = 24);

}  // namespace mtcut::cut
