#pragma once
// PNG output of rendered frames: encoded in memory (stb_image_write), then written atomically
// (core/output_file.h), so a failed run never leaves a half-written picture.
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

namespace pond {

// RGBA8 rows, top row first, `width * 4` bytes each.
std::vector<std::uint8_t> encode_png(int width, int height, std::span<const std::uint8_t> rgba);
void write_png(const std::filesystem::path& path, int width, int height, std::span<const std::uint8_t> rgba);

}  // namespace pond
