#pragma once
// NumPy .npy files (format 1.0, little-endian, C order): the dumps of pond's public contract
// (STATE.npy float32 (rows, cols, 6), TRIS.npy uint32 (T, 3), tree vertices float32 (V, 12) and
// parents int32 (V)). Writing goes through write_file_atomic; reading validates the header and
// the payload size and names what is wrong.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace pond {

enum class NpyType { f32, u32, i32 };

struct NpyArray {
  NpyType type = NpyType::f32;
  std::vector<std::size_t> shape;
  std::vector<std::byte> data;  // little-endian payload, C order

  std::size_t count() const;  // number of elements
  template <class T>
  std::span<const T> as() const {
    return {reinterpret_cast<const T*>(data.data()), data.size() / sizeof(T)};
  }
};

// Serializes a header + payload; `data` must hold product(shape) elements of `type`.
std::vector<std::byte> npy_encode(NpyType type, std::span<const std::size_t> shape,
                                  std::span<const std::byte> data);

void write_npy(const std::filesystem::path& path, NpyType type,
               std::span<const std::size_t> shape, std::span<const std::byte> data);

// Parses a whole file's bytes; `what` names it in errors. Throws InputError.
NpyArray npy_decode(std::string_view bytes, const std::string& what);
NpyArray read_npy(const std::filesystem::path& path);

const char* npy_type_name(NpyType type);  // "float32", "uint32", "int32"

}  // namespace pond
