#pragma once
// Screenshots as PNG files (stb_image_write), written atomically.

#include <cstdint>
#include <string>
#include <vector>

namespace mtcut::app::view {

// An RGBA8 image, rows top to bottom.
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // (height x width x 4)
};

// Flips rows that OpenGL read bottom-up into an Image.
Image image_from_bottom_up(int width, int height, const std::vector<std::uint8_t>& rgba_bottom_up);

// Writes `image` to `path` (temporary file, then rename). Throws InputError
// "PATH: cannot write the PNG" when it cannot.
void write_png(const std::string& path, const Image& image);

}  // namespace mtcut::app::view
