#pragma once
// Each pass's GPU time from the device's own clock: timestamp queries written around the passes of
// the frames drawn anyway, one small query pool per frame slot, read when the slot is known to be
// finished (the frame's one fence wait already covered it), never with a wait of its own. A device
// without timestamps (timestampComputeAndGraphics false, or timestampValidBits 0 on the queue)
// records nothing and says why.
#include <string_view>
#include <cstdint>
#include <string>
#include <vector>

#include "gpu/context.h"

namespace pond::render {

// A set of a frame's passes, by their place in the frame's list (PassTimestamps::names()).
using PassSet = std::vector<bool>;

// One frame's pass times in milliseconds; `ran[p]` when pass p was recorded and its times read.
struct PassTimes {
  std::uint64_t frame = 0;  // which frame (counted from 1 by the loop's begin_frame calls); 0: none yet
  PassSet ran;
  std::vector<double> ms;
};

class PassTimestamps {
 public:
  // For the passes named `names` (the frame's list, in order: "caustics", ..., "main").
  PassTimestamps(const gpu::Context& ctx, std::uint32_t slots, std::vector<std::string> names);

  const std::vector<std::string>& names() const { return names_; }
  std::size_t count() const { return names_.size(); }
  std::size_t index_of(std::string_view name) const;  // count() when there is no such pass

  bool supported() const { return supported_; }
  const std::string& unsupported_reason() const { return reason_; }  // "" when supported

  // At the start of a slot's first command buffer of a frame (outside any rendering): the slot's
  // queries reset for a new frame. The slot must be finished and collected.
  void begin_frame(const vk::raii::CommandBuffer& cmd, std::uint32_t slot);
  // Written around the commands of pass `pass` (its place in names(); scope() does both).
  void write(const vk::raii::CommandBuffer& cmd, std::uint32_t slot, std::size_t pass, bool end);
  class Scope {
   public:
    Scope(PassTimestamps& t, const vk::raii::CommandBuffer& cmd, std::uint32_t slot, std::size_t pass)
        : t_(t), cmd_(cmd), slot_(slot), pass_(pass) { t_.write(cmd_, slot_, pass_, false); }
    ~Scope() { t_.write(cmd_, slot_, pass_, true); }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;
   private:
    PassTimestamps& t_;
    const vk::raii::CommandBuffer& cmd_;
    std::uint32_t slot_;
    std::size_t pass_;
  };
  Scope scope(const vk::raii::CommandBuffer& cmd, std::uint32_t slot, std::size_t pass) { return {*this, cmd, slot, pass}; }
  // Reads the slot's last frame's times into last() (once; later calls do nothing until the
  // slot's next frame). The slot's submissions must have finished: nothing here waits.
  void collect(std::uint32_t slot);
  const PassTimes& last() const { return last_; }

 private:
  struct Slot {
    vk::raii::QueryPool pool = nullptr;
    std::uint64_t frame = 0;     // the frame written into it
    std::uint64_t written = 0;   // bit 2p: pass p's start, 2p+1: its end
    bool collected = true;
  };
  std::uint32_t queries() const { return static_cast<std::uint32_t>(2 * names_.size()); }

  std::vector<std::string> names_;
  bool supported_ = false;
  std::string reason_;
  double ns_per_tick_ = 1;
  std::uint64_t valid_mask_ = ~0ull;
  std::uint64_t frames_ = 0;
  std::vector<Slot> slots_;
  PassTimes last_;
};

}  // namespace pond::render
