#pragma once
// The GPU solver's submissions: a few command buffers, each with its fence and the host-readable
// copies of what its submission left (the displacements, the bodies) and the splashes it applied,
// used in turn. Recording the next one never waits for the last: a frame's compute is submitted
// and the CPU goes on; it waits once, when it reads what the last submission left.
#include <array>
#include <cstdint>
#include <string>

#include "gpu/buffer.h"
#include "gpu/context.h"

namespace pond::gpu {

struct Submission {
  vk::raii::CommandBuffer cmd = nullptr;
  vk::raii::Fence done = nullptr;
  Buffer displacements;  // readback: ux | uy | uz as in the state (empty where read in place)
  Buffer bodies;         // readback: the bodies' states (empty without bodies)
  Buffer splashes;       // upload: the entries of the splashes it applies (grown when needed)
  bool published = false;  // it computed the normals and made the host's copies
  std::uint64_t serial = 0;  // its place in submission order, from 1
  bool in_flight = false;
  // Its copies invalidated since it finished (each once: the host reads them several times).
  bool displacements_seen = false, bodies_seen = false;
};

class SubmissionRing {
 public:
  static constexpr std::uint32_t kSize = 3;

  // `displacement_bytes` 0: no displacement copies (the state is read in place).
  SubmissionRing(const Context& ctx, vk::DeviceSize displacement_bytes, vk::DeviceSize body_bytes);

  // The next submission's entry, its previous use finished (polled; waited for only if it still
  // runs), its command buffer reset and begun.
  Submission& begin();
  std::uint32_t index_of(const Submission& s) const { return static_cast<std::uint32_t>(&s - entries_.data()); }
  // Ends and submits the command buffer begun last; its entry becomes last().
  void submit();
  // The entry submitted last (null before any), and the same finished: waits for its fence while
  // it runs.
  const Submission* last() const { return last_ < 0 ? nullptr : &entries_[static_cast<std::size_t>(last_)]; }
  Submission* finish_last();
  // Every entry finished (waits).
  void finish_all();
  // The serial the next submission gets, and the newest serial known finished: a queue runs its
  // submissions in order, so every earlier one has finished too.
  std::uint64_t next_serial() const { return next_serial_; }
  std::uint64_t finished_serial() const { return finished_; }

 private:
  void finish(Submission& s);

  const Context& ctx_;
  vk::raii::CommandPool pool_ = nullptr;
  std::array<Submission, kSize> entries_;
  std::uint32_t next_ = 0;
  int last_ = -1;
  std::uint64_t next_serial_ = 1;
  std::uint64_t finished_ = 0;
};

}  // namespace pond::gpu
