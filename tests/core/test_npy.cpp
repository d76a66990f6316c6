// .npy encoding and decoding, and atomic output files.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/errors.h"
#include "core/npy.h"
#include "core/output_file.h"

namespace pond {
namespace {

std::string as_string(const std::vector<std::byte>& b) {
  return std::string(reinterpret_cast<const char*>(b.data()), b.size());
}

TEST(Npy, RoundTripAndHeader) {
  const float data[6] = {1, 2, 3, 4, 5, -6.5f};
  const std::size_t shape[3] = {1, 2, 3};
  const auto bytes = npy_encode(NpyType::f32, shape, std::as_bytes(std::span(data)));
  const std::string s = as_string(bytes);
  EXPECT_EQ(s.substr(0, 6), "\x93NUMPY");
  EXPECT_NE(s.find("'descr': '<f4', 'fortran_order': False, 'shape': (1, 2, 3), }"), std::string::npos);
  EXPECT_EQ((bytes.size() - sizeof data) % 64, 0u) << "header padded to 64 bytes";
  const NpyArray a = npy_decode(s, "x");
  EXPECT_EQ(a.type, NpyType::f32);
  EXPECT_EQ(a.shape, (std::vector<std::size_t>{1, 2, 3}));
  EXPECT_EQ(std::memcmp(a.data.data(), data, sizeof data), 0);
}

TEST(Npy, OneDimensionalShapeHasATrailingComma) {
  const std::int32_t v[2] = {-1, 0};
  const std::size_t shape[1] = {2};
  const std::string s = as_string(npy_encode(NpyType::i32, shape, std::as_bytes(std::span(v))));
  EXPECT_NE(s.find("'shape': (2,)"), std::string::npos);
  EXPECT_EQ(npy_decode(s, "x").type, NpyType::i32);
}

TEST(Npy, BadFilesAreNamed) {
  auto error = [](const std::string& bytes) {
    try {
      npy_decode(bytes, "f.npy");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error("hello").find("not a .npy file"), std::string::npos);
  const std::size_t shape[2] = {2, 2};
  const float d[4] = {};
  std::string good = as_string(npy_encode(NpyType::f32, shape, std::as_bytes(std::span(d))));
  EXPECT_NE(error(good.substr(0, good.size() - 1)).find("payload is 15 bytes"), std::string::npos);
  EXPECT_NE(error(good.substr(0, 20)).find("truncated"), std::string::npos);
  std::string f8 = good;
  f8.replace(f8.find("<f4"), 3, "<f8");
  EXPECT_NE(error(f8).find("unsupported dtype '<f8'"), std::string::npos);
}

TEST(OutputFile, AtomicWriteNeverLeavesPartialFiles) {
  const auto dir = std::filesystem::temp_directory_path() / "pond_test_output";
  std::filesystem::create_directories(dir);
  const auto path = dir / "a.bin";
  const std::byte one[3] = {std::byte{1}, std::byte{2}, std::byte{3}};
  write_file_atomic(path, one);
  EXPECT_EQ(std::filesystem::file_size(path), 3u);
  EXPECT_THROW(write_file_atomic(dir / "missing" / "b.bin", one), InputError);
  EXPECT_THROW(check_output_path(dir), InputError);  // a folder
  if (std::filesystem::exists("/dev/full")) {
    EXPECT_THROW(write_file_atomic("/dev/full", one), RuntimeError);
    EXPECT_TRUE(std::filesystem::is_character_file("/dev/full")) << "the device must survive";
  }
  for (const auto& e : std::filesystem::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find(".tmp."), std::string::npos) << "leftover temp file";
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace pond
