#pragma once
// A few lines that read a little-endian .npy 1.0 file for the test checkers (tris_check,
// tree_check), written from the format's description and not with pond's reader (src/core/npy),
// so a checker does not trust the code whose output it checks. Exits 2 naming the file when it
// cannot be read as `descr` (e.g. "<f4").
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace pond::test {

template <class T>
struct PlainNpy {
  std::vector<std::size_t> shape;
  std::vector<T> data;
};

template <class T>
PlainNpy<T> read_plain_npy(const std::string& path, const char* descr) {
  auto bad = [&](const char* what) {
    std::fprintf(stderr, "%s: %s\n", path.c_str(), what);
    std::exit(2);
  };
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() < 10 || bytes.compare(0, 6, "\x93NUMPY") != 0 || bytes[6] != 1) bad("not a .npy 1.0 file");
  const std::size_t header_len = static_cast<unsigned char>(bytes[8]) | static_cast<std::size_t>(static_cast<unsigned char>(bytes[9])) << 8;
  const std::string header = bytes.substr(10, header_len);
  if (header.find(std::string("'descr': '") + descr + "'") == std::string::npos) bad("another element type");
  const std::size_t open = header.find("'shape': ("), close = header.find(')', open);
  if (open == std::string::npos || close == std::string::npos) bad("no shape");
  PlainNpy<T> out;
  std::stringstream dims(header.substr(open + 10, close - open - 10));
  for (std::string d; std::getline(dims, d, ',');)
    if (d.find_first_not_of(' ') != std::string::npos) out.shape.push_back(static_cast<std::size_t>(std::stoull(d)));
  std::size_t count = 1;
  for (std::size_t d : out.shape) count *= d;
  if (bytes.size() - 10 - header_len != count * sizeof(T)) bad("payload size differs from the shape's");
  out.data.resize(count);
  std::memcpy(out.data.data(), bytes.data() + 10 + header_len, count * sizeof(T));
  return out;
}

}  // namespace pond::test
