// Fuzz target: the .npy reader (npy_decode). A file it accepts must hold exactly the payload its
// shape needs, and must survive a round trip through npy_encode unchanged.
#include <string_view>

#include "core/errors.h"
#include "core/npy.h"
#include "targets.h"

namespace pond::fuzz {

int npy(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  NpyArray a;
  try {
    a = npy_decode(bytes, "fuzz.npy");
  } catch (const InputError& e) {
    if (std::string_view(e.what()).empty()) property_failed("InputError without a message");
    return 0;
  }
  if (a.data.size() != a.count() * 4) property_failed("payload size differs from the shape's");
  const std::vector<std::byte> again = npy_encode(a.type, a.shape, a.data);
  const NpyArray b = npy_decode(std::string_view(reinterpret_cast<const char*>(again.data()), again.size()),
                                "round trip");
  if (b.type != a.type || b.shape != a.shape || b.data != a.data) property_failed("round trip differs");
  return 0;
}

}  // namespace pond::fuzz
