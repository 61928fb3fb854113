#include "engine/mt/index_set.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

#include "engine/ids.h"

namespace mtcut::engine {
namespace {

TEST(IndexSet, MatchesAStdSetUnderRandomEdits) {
  IndexSet<TetId> set;
  set.grow(100);
  std::set<std::int32_t> reference;
  std::mt19937 rng(4);
  for (int step = 0; step < 5000; ++step) {
    const TetId t(static_cast<std::int32_t>(rng() % 100));
    if (set.contains(t)) {
      set.erase(t);
      reference.erase(t.value);
    } else {
      set.insert(t);
      reference.insert(t.value);
    }
    ASSERT_EQ(set.size(), reference.size());
  }
  std::set<std::int32_t> members;
  for (TetId t : set.members()) members.insert(t.value);
  EXPECT_EQ(members, reference);
  set.grow(200);
  EXPECT_EQ(set.size(), reference.size());
  EXPECT_FALSE(set.contains(TetId(150)));
  set.clear();
  EXPECT_TRUE(set.empty());
  for (std::int32_t i = 0; i < 100; ++i) EXPECT_FALSE(set.contains(TetId(i)));
}

}  // namespace
}  // namespace mtcut::engine
