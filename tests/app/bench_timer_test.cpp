#include "app/bench_timer.h"

#include <gtest/gtest.h>

#include <string>

namespace mtcut::app {
namespace {

// Each batch warms up once, then the two run in alternation, one round per
// batch: the pairs the ratio is taken over see the same moment's load.
TEST(BenchTimer, PairedBatchesAlternate) {
  std::string order;
  const PairedTiming t = time_batch_pair(4, [&] { order += 'a'; }, [&] { order += 'b'; });
  EXPECT_EQ(order, "ababababab");
  EXPECT_EQ(t.a.batches, 4);
  EXPECT_EQ(t.b.batches, 4);
  EXPECT_GT(t.a_over_b, 0.0);
}

}  // namespace
}  // namespace mtcut::app
