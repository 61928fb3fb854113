#include "app/view/surface_colors.h"

#include <gtest/gtest.h>

namespace mtcut::app::view {
namespace {

// The hue tests of the screenshot test, on unshaded colours.
bool organ_like(const glm::vec3& c) { return c.r > 1.6f * c.g && c.r > 1.6f * c.b; }
bool green_like(const glm::vec3& c) { return c.g > 1.5f * c.r && c.g > 1.5f * c.b; }
bool neutral(const glm::vec3& c) { return std::abs(c.r - c.g) < 0.03f && std::abs(c.g - c.b) < 0.03f; }

TEST(SurfaceColors, PiecesCutsFloorAndBackgroundDiffer) {
  EXPECT_TRUE(organ_like(piece_color(0)));
  for (int p = 1; p < 6; ++p) {
    EXPECT_FALSE(organ_like(piece_color(p))) << p;
    EXPECT_FALSE(green_like(piece_color(p))) << p;
    EXPECT_FALSE(neutral(piece_color(p))) << p;
  }
  EXPECT_TRUE(green_like(kCutColor));
  EXPECT_TRUE(neutral(kFloorLight) && neutral(kFloorDark));
  EXPECT_FALSE(neutral(kBackgroundColor));
  EXPECT_EQ(piece_color(6), piece_color(0));  // the tints cycle
}

TEST(SurfaceColors, LevelRampRunsFromBlueToRed) {
  const glm::vec3 finest = level_color(0, 8), coarsest = level_color(8, 8);
  EXPECT_GT(finest.b, finest.r);
  EXPECT_GT(coarsest.r, coarsest.b);
  EXPECT_EQ(level_color(0, 0), finest);  // a single level is the finest colour
}

TEST(SurfaceColors, CornersTakeTheirFaceColour) {
  SurfaceTopology s;
  s.faces.resize(2);
  s.face_piece = {0, 1};
  s.face_cut = {1, 0};
  s.face_level = {0, 3};
  s.max_level = 3;
  const auto pieces = corner_colors(s, ColorMode::kPieces);
  ASSERT_EQ(pieces.size(), 6u);
  EXPECT_EQ(pieces[0], kCutColor);
  EXPECT_EQ(pieces[5], piece_color(1));
  const auto levels = corner_colors(s, ColorMode::kLodLevels);
  EXPECT_EQ(levels[0], level_color(0, 3));
  EXPECT_EQ(levels[3], level_color(3, 3));
}

}  // namespace
}  // namespace mtcut::app::view
