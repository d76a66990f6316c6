// Fuzz target: the checkpoint reader (scene/checkpoint.h). An input that starts like a checkpoint
// is read as a whole file; any other is taken as a payload and sealed first, so the fuzzer reaches
// the payload's reader past the checksum. Every refusal is an InputError; a checkpoint it accepts
// must resume on the CPU, step, and save back to an equal checkpoint.
#include <string_view>
#include <vector>

#include "core/errors.h"
#include "scene/checkpoint.h"
#include "sim/diagnostics.h"
#include "targets.h"

namespace pond::fuzz {

int checkpoint(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  std::vector<std::byte> sealed;
  std::string_view file = bytes;
  if (!bytes.starts_with("PONDCKPT")) {
    sealed = scene::seal_checkpoint(std::as_bytes(std::span(data, size)));
    file = std::string_view(reinterpret_cast<const char*>(sealed.data()), sealed.size());
  }
  scene::Checkpoint c;
  try {
    c = scene::decode_checkpoint(file, "fuzz.ckpt");
  } catch (const InputError& e) {
    if (std::string_view(e.what()).empty()) property_failed("InputError without a message");
    return 0;
  }
  if (c.image.state.nodes() != static_cast<std::size_t>(c.scene.grid.rows) * static_cast<std::size_t>(c.scene.grid.cols))
    property_failed("a state of another size than its grid was accepted");
  if (c.scene.grid.rows * c.scene.grid.cols > 64 * 64) return 0;  // keep each input fast
  const sim::SolverChoice scalar{.gpu = false, .backend = sim::Backend::scalar, .threads = 1};
  std::unique_ptr<sim::Session> session;
  try {
    session = scene::resume_session(c, scalar, {});
  } catch (const InputError& e) {  // a restore the session refuses (the wind's trees, the rain's state)
    if (std::string_view(e.what()).empty()) property_failed("InputError without a message");
    return 0;
  }
  if (session->steps_done() != c.image.steps) property_failed("the resumed step count differs");
  const sim::SessionImage image = session->image();
  if (sim::state_hash(image.state, session->model()) != sim::state_hash(c.image.state, session->model()))
    property_failed("the resumed state differs from the checkpoint's");
  try {
    session->advance(2);
  } catch (const InputError& e) {  // a saved state that blows up: said as bad input
    if (std::string_view(e.what()).empty()) property_failed("InputError without a message");
  }
  return 0;
}

}  // namespace pond::fuzz
