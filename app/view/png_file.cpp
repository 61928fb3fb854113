#include "app/view/png_file.h"

#include <cstring>
#include <stb_image_write.h>

#include "engine/atomic_file.h"
#include "engine/input_error.h"

namespace mtcut::app::view {

Image image_from_bottom_up(int width, int height, const std::vector<std::uint8_t>& rgba_bottom_up) {
  Image image{width, height, std::vector<std::uint8_t>(rgba_bottom_up.size())};
  const std::size_t row = static_cast<std::size_t>(width) * 4;
  for (int y = 0; y < height; ++y)
    std::memcpy(image.rgba.data() + static_cast<std::size_t>(y) * row,
                rgba_bottom_up.data() + static_cast<std::size_t>(height - 1 - y) * row, row);
  return image;
}

void write_png(const std::string& path, const Image& image) {
  std::vector<std::uint8_t> encoded;
  const auto append = [](void* context, void* data, int size) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(context);
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    out->insert(out->end(), bytes, bytes + size);
  };
  if (image.width <= 0 || image.height <= 0 ||
      !stbi_write_png_to_func(append, &encoded, image.width, image.height, 4, image.rgba.data(), image.width * 4))
    throw engine::InputError(path + ": cannot encode the PNG");
  engine::write_stream_atomically(path, [&](std::ostream& out) {
    out.write(reinterpret_cast<const char*>(encoded.data()), static_cast<std::streamsize>(encoded.size()));
  });
}

}  // namespace mtcut::app::view
