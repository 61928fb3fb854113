#include "app/view/step_clock.h"

#include <gtest/gtest.h>

namespace mtcut::app::view {
namespace {

// Times are binary fractions so that the step counts are exact.

TEST(StepClock, SpendsWholeStepsAndCarriesTheRemainder) {
  StepClock c(0.25, 4);
  EXPECT_EQ(c.advance(0.625), 2);   // 0.125 left
  EXPECT_EQ(c.advance(0.1875), 1);  // 0.3125 due
  EXPECT_EQ(c.advance(0.0), 0);
  EXPECT_EQ(c.steps(), 3u);
  EXPECT_EQ(c.dropped_steps(), 0u);
}

TEST(StepClock, FallingBehindDropsStepsInsteadOfPilingThemUp) {
  StepClock c(0.25, 2);
  EXPECT_EQ(c.advance(25.0), 2);  // a hitch: 100 steps due, 2 run
  EXPECT_EQ(c.dropped_steps(), 98u);
  EXPECT_EQ(c.advance(0.25), 1);  // no debt left over
  c.drop(3);
  EXPECT_EQ(c.dropped_steps(), 101u);
}

TEST(StepClock, ClearForgetsAccumulatedTime) {
  StepClock c(0.25);
  EXPECT_EQ(c.advance(0.1875), 0);
  c.clear();
  EXPECT_EQ(c.advance(0.125), 0);  // 0.3125 without the clear
}

}  // namespace
}  // namespace mtcut::app::view
