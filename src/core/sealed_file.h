#pragma once
// A file that says what it is and whether it is whole: a header with a magic, a format version, a
// hash of the payload's layout and the byte order it was written in, then the payload's size and
// checksum (FNV-1a, 64 bits), then the payload. Reading refuses, with one line naming the file and
// what is wrong, a file that is not one, is of another version, layout or byte order, is truncated
// or longer than it says, or whose bytes do not match their checksum (pond's checkpoints,
// scene/checkpoint.h). Writing is atomic (core/output_file.h).
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace pond {

struct SealedFormat {
  std::string_view magic;  // exactly 8 bytes
  std::uint32_t version;
  std::uint64_t layout;    // a hash of what the payload holds and how (layout_hash())
  const char* kind;        // for messages: "a pond checkpoint"
};

// FNV-1a of `text`: a layout's description (field names, types, sizes) as its hash.
std::uint64_t layout_hash(std::string_view text);
std::uint64_t fnv1a(std::span<const std::byte> bytes);

// The file's bytes for `payload`, and the same written atomically to `path`.
std::vector<std::byte> seal(const SealedFormat& format, std::span<const std::byte> payload);
void write_sealed(const std::filesystem::path& path, const SealedFormat& format, std::span<const std::byte> payload);

// The payload of `bytes` (a whole file's, named `name` in errors). Throws InputError.
std::string unseal(std::string_view bytes, const SealedFormat& format, const std::string& name);
std::string read_sealed(const std::filesystem::path& path, const SealedFormat& format);

}  // namespace pond
