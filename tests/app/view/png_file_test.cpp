#include "app/view/png_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <stb_image.h>

#include "engine/input_error.h"

namespace mtcut::app::view {
namespace {

TEST(PngFile, RowsAreFlippedAndTheFileReadsBack) {
  // 2 x 2, bottom-up: the bottom row red, the top row blue.
  const std::vector<std::uint8_t> gl = {255, 0, 0, 255, 255, 0, 0, 255, 0, 0, 255, 255, 0, 0, 255, 255};
  const Image image = image_from_bottom_up(2, 2, gl);
  EXPECT_EQ(image.rgba[2], 255);  // top-left is blue
  const auto path = std::filesystem::temp_directory_path() / ("mtcut-png-" + std::to_string(::getpid()) + ".png");
  write_png(path.string(), image);
  int w = 0, h = 0, n = 0;
  unsigned char* back = stbi_load(path.string().c_str(), &w, &h, &n, 4);
  ASSERT_NE(back, nullptr);
  EXPECT_EQ(w, 2);
  EXPECT_EQ(h, 2);
  EXPECT_EQ(std::vector<std::uint8_t>(back, back + 16), image.rgba);
  stbi_image_free(back);
  std::filesystem::remove(path);
}

TEST(PngFile, AnUnwritablePathIsAnInputError) {
  const Image image{1, 1, {0, 0, 0, 255}};
  EXPECT_THROW(write_png("/nonexistent-dir/x.png", image), engine::InputError);
  EXPECT_THROW(write_png("/tmp/empty.png", Image{}), engine::InputError);
}

}  // namespace
}  // namespace mtcut::app::view
