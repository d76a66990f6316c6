#include "core/png.h"

#include "core/errors.h"
#include "core/output_file.h"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image_write.h>

namespace pond {
namespace {

void append(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(context);
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

std::vector<std::uint8_t> encode_png(int width, int height, std::span<const std::uint8_t> rgba) {
  if (width <= 0 || height <= 0 || rgba.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4)
    throw RuntimeError("encode_png: the pixel buffer does not match " + std::to_string(width) + "x" + std::to_string(height));
  std::vector<std::uint8_t> png;
  if (!stbi_write_png_to_func(append, &png, width, height, 4, rgba.data(), width * 4) || png.empty())
    throw RuntimeError("PNG encoding failed");
  return png;
}

void write_png(const std::filesystem::path& path, int width, int height, std::span<const std::uint8_t> rgba) {
  const std::vector<std::uint8_t> png = encode_png(width, height, rgba);
  write_file_atomic(path, std::as_bytes(std::span(png)));
}

}  // namespace pond
