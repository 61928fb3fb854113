// Placeholder until the cut layer lands: the binary links against mtcut::cut.
#include <gtest/gtest.h>

#include "engine/tet_geometry.h"

TEST(CutLayer, LinksAgainstEngine) {
  using mtcut::engine::Vec3;
  EXPECT_DOUBLE_EQ(mtcut::engine::signed_volume(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)), 1.0 / 6.0);
}
