#include "cut/lut/split_configs.h"

#include <algorithm>
#include <array>

#include "cut/lut/cut_trace.h"
#include "engine/tet_geometry.h"

namespace mtcut::cut {

namespace {

// Key bits (TetConfig::key): the cut edges at 8..13, the order's Lehmer
// code at 14..18 (0 for the identity order).
constexpr int kActiveShift = 8, kOrderShift = 14;
constexpr std::uint32_t kOrderBits = 31u << kOrderShift;

// Whether a set of cut edges (bit k: edge k) cuts two edges of some face.
constexpr bool splits_a_face_into_a_quad(unsigned active) {
  for (const auto& f : engine::kTetFaces) {
    int n = 0;
    for (int j = 0; j < 3; ++j) n += active >> edge_between(f[j], f[(j + 1) % 3]) & 1;
    if (n == 2) return true;
  }
  return false;
}

// By cut-edge mask: the lookup runs for every tet a cut splits.
constexpr std::array<bool, 64> kOrderMatters = [] {
  std::array<bool, 64> table{};
  for (unsigned m = 0; m < 64; ++m) table[m] = splits_a_face_into_a_quad(m);
  return table;
}();

}  // namespace

bool order_matters(const TetConfig& c) { return kOrderMatters[c.key() >> kActiveShift & 63]; }

std::uint32_t table_key(const TetConfig& c) {
  const std::uint32_t key = c.key();
  return kOrderMatters[key >> kActiveShift & 63] ? key : key & ~kOrderBits;
}

std::vector<TetConfig> all_cut_configs(int orders) {
  std::vector<std::array<std::uint8_t, 4>> ranks;
  std::array<std::uint8_t, 4> r = {0, 1, 2, 3};
  do ranks.push_back(r);
  while (std::next_permutation(r.begin(), r.end()));
  std::vector<TetConfig> out;
  for (int states = 0; states < 256; ++states) {
    TetConfig c;
    for (int i = 0; i < 4; ++i) c.vertex[i] = static_cast<VertexState>(states >> (2 * i) & 3);
    std::vector<int> straddling;
    for (int k = 0; k < 6; ++k)
      if (c.straddles(k)) straddling.push_back(k);
    for (int mask = 0; mask < (1 << straddling.size()); ++mask) {
      c.covered = 0;
      for (std::size_t j = 0; j < straddling.size(); ++j)
        if (mask >> j & 1) c.covered |= static_cast<std::uint8_t>(1u << straddling[j]);
      if (!c.is_cut()) continue;
      // A bent cut surface is implied by a vertex on the cut; without one it
      // is its own variant (cut points moved off the plane).
      const bool on = std::any_of(c.vertex.begin(), c.vertex.end(), is_on);
      for (int bent = on ? 1 : 0; bent < 2; ++bent)
        for (int o = 0; o < (order_matters(c) ? orders : 1); ++o) {
          c.rank = ranks[static_cast<std::size_t>(o * 24 / orders)];
          c.bent = bent == 1;
          out.push_back(c);
        }
    }
  }
  return out;
}

}  // namespace mtcut::cut
