#pragma once
// A stable least-significant-digit radix sort on keys of a few 64-bit words.
//
// Why. The MT cutter numbers the points a cut makes by their keys (ids and
// kinds packed into three words) so that the numbering does not depend on the
// order it met them in. Table 1's largest cut makes about 5,000 points, and
// std::sort's comparisons of three words took 0.28 ms of its 5.5. Most bytes
// of such keys are equal in every item (ids are far below 2^32): one pass
// finds them and they are neither counted nor sorted on; the rest is a
// handful of linear passes.

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace mtcut::engine {

// Sorts `items` by key(item), an std::array<std::uint64_t, W> compared
// lexicographically (word 0 the most significant). Stable. `scratch` is
// storage it may reuse (left with unspecified contents).
template <std::size_t W, class T, class Key>
void radix_sort(std::vector<T>& items, std::vector<T>& scratch, Key&& key) {
  const std::size_t n = items.size();
  if (n < 2) return;
  constexpr std::size_t kDigits = 8 * W;  // bytes of the key, least significant last
  // The bytes some items differ in (all others are skipped): where the OR
  // and the AND of every key disagree.
  std::array<std::uint64_t, W> any{}, all;
  all.fill(~std::uint64_t{0});
  for (const T& item : items) {
    const std::array<std::uint64_t, W> k = key(item);
    for (std::size_t w = 0; w < W; ++w) any[w] |= k[w], all[w] &= k[w];
  }
  std::array<std::size_t, kDigits> digits;  // (word, byte) as 8 w + b, least significant first
  std::size_t n_digits = 0;
  for (std::size_t w = W; w-- > 0;)
    for (std::size_t b = 0; b < 8; ++b)
      if (((any[w] ^ all[w]) >> (8 * b)) & 0xff) digits[n_digits++] = 8 * w + b;
  std::vector<std::array<std::uint32_t, 256>> counts(n_digits);
  for (auto& c : counts) c.fill(0);
  for (const T& item : items) {
    const std::array<std::uint64_t, W> k = key(item);
    for (std::size_t d = 0; d < n_digits; ++d) ++counts[d][(k[digits[d] / 8] >> (8 * (digits[d] % 8))) & 0xff];
  }
  scratch.resize(n);
  for (std::size_t d = 0; d < n_digits; ++d) {
    std::array<std::uint32_t, 256>& count = counts[d];
    std::uint32_t offset = 0;
    for (std::uint32_t& c : count) offset += std::exchange(c, offset);
    const std::size_t w = digits[d] / 8, shift = 8 * (digits[d] % 8);
    for (const T& item : items) scratch[count[(key(item)[w] >> shift) & 0xff]++] = item;
    items.swap(scratch);
  }
}

}  // namespace mtcut::engine
