#include "core/sealed_file.h"

#include <cstring>
#include <vector>

#include "core/errors.h"
#include "core/output_file.h"

namespace pond {
namespace {

constexpr std::uint32_t kByteOrder = 0x01020304;  // as the writer's memory holds it
constexpr std::size_t kHeader = 8 + 4 + 4 + 8 + 8 + 8;

template <class T>
void put(std::vector<std::byte>& out, T value) {
  const auto* p = reinterpret_cast<const std::byte*>(&value);
  out.insert(out.end(), p, p + sizeof value);
}

template <class T>
T get(std::string_view bytes, std::size_t at) {
  T value;
  std::memcpy(&value, bytes.data() + at, sizeof value);
  return value;
}

}  // namespace

std::uint64_t fnv1a(std::span<const std::byte> bytes) {
  std::uint64_t h = 1469598103934665603ull;
  for (std::byte b : bytes) {
    h ^= static_cast<std::uint64_t>(b);
    h *= 1099511628211ull;
  }
  return h;
}

std::uint64_t layout_hash(std::string_view text) { return fnv1a(std::as_bytes(std::span(text.data(), text.size()))); }

void write_sealed(const std::filesystem::path& path, const SealedFormat& format, std::span<const std::byte> payload) {
  write_file_atomic(path, seal(format, payload));
}

std::vector<std::byte> seal(const SealedFormat& format, std::span<const std::byte> payload) {
  if (format.magic.size() != 8) throw InternalError("a sealed file's magic is 8 bytes");
  std::vector<std::byte> out;
  out.reserve(kHeader + payload.size());
  const auto* magic = reinterpret_cast<const std::byte*>(format.magic.data());
  out.insert(out.end(), magic, magic + 8);
  put(out, format.version);
  put(out, kByteOrder);
  put(out, format.layout);
  put(out, static_cast<std::uint64_t>(payload.size()));
  put(out, fnv1a(payload));
  out.insert(out.end(), payload.begin(), payload.end());
  return out;
}

std::string unseal(std::string_view bytes, const SealedFormat& format, const std::string& name) {
  const std::string file = "'" + name + "'";
  if (bytes.size() < 8 || bytes.substr(0, 8) != format.magic)
    throw InputError(file + " is not " + format.kind + " (it does not start with " + std::string(format.magic) + ")");
  if (bytes.size() < kHeader)
    throw InputError(file + " is truncated: " + std::to_string(bytes.size()) + " bytes, less than its header");
  const auto order = get<std::uint32_t>(bytes, 12);
  if (order != kByteOrder)
    throw InputError(file + " was written on a machine of the other byte order; this one cannot read it");
  const auto version = get<std::uint32_t>(bytes, 8);
  if (version != format.version)
    throw InputError(file + " is " + format.kind + " of format version " + std::to_string(version) +
                     "; this pond reads version " + std::to_string(format.version));
  if (get<std::uint64_t>(bytes, 16) != format.layout)
    throw InputError(file + " holds another layout than this pond's (a build that lays its state out otherwise "
                            "wrote it)");
  const auto size = get<std::uint64_t>(bytes, 24);
  const std::size_t have = bytes.size() - kHeader;
  if (size > have)
    throw InputError(file + " is truncated: " + std::to_string(have) + " of " + std::to_string(size) + " bytes");
  if (size < have)
    throw InputError(file + " has " + std::to_string(have - size) + " bytes after its end");
  const std::string_view payload = bytes.substr(kHeader);
  if (fnv1a(std::as_bytes(std::span(payload.data(), payload.size()))) != get<std::uint64_t>(bytes, 32))
    throw InputError(file + " is corrupt: its bytes do not match their checksum");
  return std::string(payload);
}

std::string read_sealed(const std::filesystem::path& path, const SealedFormat& format) {
  return unseal(read_file(path), format, path.string());
}

}  // namespace pond
