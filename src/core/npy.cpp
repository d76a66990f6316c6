#include "core/npy.h"

#include <bit>
#include <cstring>
#include <limits>

#include "core/errors.h"
#include "core/output_file.h"
#include "core/text.h"

namespace pond {
namespace {

static_assert(std::endian::native == std::endian::little, "pond writes little-endian .npy files");

const char* descr(NpyType t) {
  switch (t) {
    case NpyType::f32: return "<f4";
    case NpyType::u32: return "<u4";
    case NpyType::i32: return "<i4";
  }
  return "";
}

std::string shape_text(std::span<const std::size_t> shape) {
  std::string s = "(";
  for (std::size_t i = 0; i < shape.size(); ++i) {
    s += std::to_string(shape[i]);
    if (shape.size() == 1 || i + 1 < shape.size()) s += ",";
    if (i + 1 < shape.size()) s += " ";
  }
  return s + ")";
}

// Finds `'key':` in the header dict and returns the text after it.
std::string_view after_key(std::string_view header, std::string_view key, const std::string& what) {
  const std::string quoted = "'" + std::string(key) + "'";
  std::size_t p = header.find(quoted);
  if (p == std::string_view::npos) throw InputError(what + ": .npy header has no '" + std::string(key) + "'");
  p = header.find(':', p + quoted.size());
  if (p == std::string_view::npos) throw InputError(what + ": malformed .npy header");
  p = header.find_first_not_of(' ', p + 1);
  if (p == std::string_view::npos) throw InputError(what + ": malformed .npy header");
  return header.substr(p);
}

}  // namespace

const char* npy_type_name(NpyType type) {
  switch (type) {
    case NpyType::f32: return "float32";
    case NpyType::u32: return "uint32";
    case NpyType::i32: return "int32";
  }
  return "?";
}

std::size_t NpyArray::count() const {
  std::size_t n = 1;
  for (std::size_t d : shape) n *= d;
  return n;
}

std::vector<std::byte> npy_encode(NpyType type, std::span<const std::size_t> shape,
                                  std::span<const std::byte> data) {
  std::string header = "{'descr': '" + std::string(descr(type)) +
                       "', 'fortran_order': False, 'shape': " + shape_text(shape) + ", }";
  // Magic (6) + version (2) + length (2) + header + '\n', padded to a multiple of 64 bytes.
  std::size_t total = 10 + header.size() + 1;
  header.append((64 - total % 64) % 64, ' ');
  header += '\n';
  std::vector<std::byte> out(10 + header.size() + data.size());
  const unsigned char magic[8] = {0x93, 'N', 'U', 'M', 'P', 'Y', 1, 0};
  std::memcpy(out.data(), magic, 8);
  const auto len = static_cast<std::uint16_t>(header.size());
  out[8] = std::byte(len & 0xff);
  out[9] = std::byte(len >> 8);
  std::memcpy(out.data() + 10, header.data(), header.size());
  if (!data.empty()) std::memcpy(out.data() + 10 + header.size(), data.data(), data.size());
  return out;
}

void write_npy(const std::filesystem::path& path, NpyType type,
               std::span<const std::size_t> shape, std::span<const std::byte> data) {
  write_file_atomic(path, npy_encode(type, shape, data));
}

NpyArray npy_decode(std::string_view bytes, const std::string& what) {
  if (bytes.size() < 10 || std::memcmp(bytes.data(), "\x93NUMPY", 6) != 0)
    throw InputError(what + ": not a .npy file");
  const auto major = static_cast<unsigned char>(bytes[6]);
  std::size_t header_len = 0, header_start = 0;
  if (major == 1) {
    header_len = static_cast<unsigned char>(bytes[8]) | (static_cast<unsigned char>(bytes[9]) << 8);
    header_start = 10;
  } else if (major == 2 || major == 3) {
    if (bytes.size() < 12) throw InputError(what + ": truncated .npy header");
    for (int i = 3; i >= 0; --i) header_len = header_len * 256 + static_cast<unsigned char>(bytes[8 + i]);
    header_start = 12;
  } else {
    throw InputError(what + ": unsupported .npy version " + std::to_string(major));
  }
  if (header_start + header_len > bytes.size()) throw InputError(what + ": truncated .npy header");
  const std::string_view header = bytes.substr(header_start, header_len);

  NpyArray a;
  const std::string_view d = after_key(header, "descr", what);
  if (d.starts_with("'<f4'")) a.type = NpyType::f32;
  else if (d.starts_with("'<u4'")) a.type = NpyType::u32;
  else if (d.starts_with("'<i4'")) a.type = NpyType::i32;
  else {
    const std::size_t end = d.find(',');
    throw InputError(what + ": unsupported dtype " + escaped(d.substr(0, end)) +
                     " (expected float32, uint32 or int32)");
  }
  if (!after_key(header, "fortran_order", what).starts_with("False"))
    throw InputError(what + ": Fortran-ordered arrays are not supported");
  std::string_view s = after_key(header, "shape", what);
  if (s.empty() || s[0] != '(') throw InputError(what + ": malformed shape in .npy header");
  std::size_t p = 1;
  std::size_t elements = 1;
  while (p < s.size() && s[p] != ')') {
    if (s[p] == ' ' || s[p] == ',') { ++p; continue; }
    if (s[p] < '0' || s[p] > '9') throw InputError(what + ": malformed shape in .npy header");
    std::size_t v = 0;
    while (p < s.size() && s[p] >= '0' && s[p] <= '9') {
      if (v > (std::numeric_limits<std::size_t>::max() - 9) / 10)
        throw InputError(what + ": shape too large in .npy header");
      v = v * 10 + static_cast<std::size_t>(s[p++] - '0');
    }
    if (v != 0 && elements > std::numeric_limits<std::size_t>::max() / 4 / v)
      throw InputError(what + ": shape too large in .npy header");
    elements *= v;
    a.shape.push_back(v);
  }
  if (p >= s.size()) throw InputError(what + ": malformed shape in .npy header");
  const std::size_t payload = elements * 4;
  const std::size_t available = bytes.size() - header_start - header_len;
  if (available != payload)
    throw InputError(what + ": payload is " + std::to_string(available) + " bytes, shape " +
                     shape_text(a.shape) + " needs " + std::to_string(payload));
  a.data.resize(payload);
  if (payload) std::memcpy(a.data.data(), bytes.data() + header_start + header_len, payload);
  return a;
}

NpyArray read_npy(const std::filesystem::path& path) {
  const std::string bytes = read_file(path);
  return npy_decode(bytes, quote(path.string()));
}

}  // namespace pond
