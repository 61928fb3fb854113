#include "engine/radix_sort.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <vector>

namespace mtcut::engine {
namespace {

struct Item {
  std::array<std::uint64_t, 3> key;
  int payload;  // the input position: checks stability
};

std::array<std::uint64_t, 3> key_of(const Item& item) { return item.key; }

// The same order as a stable comparison sort, over keys drawn so that some
// bytes vary in every word (ids below 2^17, as the cutter's), some bytes of
// whole words are shared, and repeated keys keep their input order.
TEST(RadixSort, SortsLikeAStableComparisonSort) {
  std::mt19937_64 rng(7);
  for (const std::size_t n : {0, 1, 2, 3, 100, 5000}) {
    for (const std::uint64_t range : {std::uint64_t{3}, std::uint64_t{1} << 17, ~std::uint64_t{0}}) {
      std::vector<Item> items(n);
      for (std::size_t i = 0; i < n; ++i) {
        items[i].key = {rng() % 4, rng() % range << 32 | rng() % range, i % 2 == 0 ? 0 : rng() % range};
        items[i].payload = static_cast<int>(i);
      }
      std::vector<Item> expected = items;
      std::stable_sort(expected.begin(), expected.end(), [](const Item& a, const Item& b) { return a.key < b.key; });
      std::vector<Item> scratch;
      radix_sort<3>(items, scratch, key_of);
      ASSERT_EQ(items.size(), expected.size());
      for (std::size_t i = 0; i < n; ++i) {
        EXPECT_EQ(items[i].key, expected[i].key) << "n " << n << ", range " << range << ", at " << i;
        EXPECT_EQ(items[i].payload, expected[i].payload) << "n " << n << ", range " << range << ", at " << i;
      }
    }
  }
}

// Every key equal: every pass is skipped and the input order stays.
TEST(RadixSort, EqualKeysKeepTheirOrder) {
  std::vector<Item> items(50, Item{{1, 2, 3}, 0});
  for (std::size_t i = 0; i < items.size(); ++i) items[i].payload = static_cast<int>(i);
  std::vector<Item> scratch;
  radix_sort<3>(items, scratch, key_of);
  for (std::size_t i = 0; i < items.size(); ++i) EXPECT_EQ(items[i].payload, static_cast<int>(i));
}

}  // namespace
}  // namespace mtcut::engine
