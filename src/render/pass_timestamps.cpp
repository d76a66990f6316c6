#include "render/pass_timestamps.h"

#include "core/errors.h"

namespace pond::render {

PassTimestamps::PassTimestamps(const gpu::Context& ctx, std::uint32_t slots, std::vector<std::string> names)
    : names_(std::move(names)) {
  if (2 * names_.size() > 64) throw InternalError("more passes than PassTimestamps counts");
  last_.ran.assign(names_.size(), false);
  last_.ms.assign(names_.size(), 0.0);
  const vk::PhysicalDeviceLimits limits = ctx.physical().getProperties().limits;
  const std::uint32_t bits = ctx.physical().getQueueFamilyProperties()[ctx.queue_family()].timestampValidBits;
  if (!limits.timestampComputeAndGraphics) reason_ = "timestampComputeAndGraphics is false";
  if (bits == 0) reason_ += std::string(reason_.empty() ? "" : ", ") + "timestampValidBits is 0 on its queue";
  supported_ = reason_.empty();
  if (!supported_) return;
  ns_per_tick_ = limits.timestampPeriod;
  valid_mask_ = bits >= 64 ? ~0ull : (1ull << bits) - 1;
  slots_.resize(slots);
  for (std::uint32_t k = 0; k < slots; ++k) {
    slots_[k].pool = vk::raii::QueryPool(
        ctx.device(), vk::QueryPoolCreateInfo{.queryType = vk::QueryType::eTimestamp, .queryCount = queries()});
    ctx.name(slots_[k].pool, "pass timestamps, slot " + std::to_string(k));
  }
}

void PassTimestamps::begin_frame(const vk::raii::CommandBuffer& cmd, std::uint32_t slot) {
  if (!supported_) return;
  Slot& s = slots_[slot];
  cmd.resetQueryPool(*s.pool, 0, queries());
  s.frame = ++frames_;
  s.written = 0;
  s.collected = false;
}

std::size_t PassTimestamps::index_of(std::string_view name) const {
  std::size_t p = 0;
  while (p < names_.size() && names_[p] != name) ++p;
  return p;
}

void PassTimestamps::write(const vk::raii::CommandBuffer& cmd, std::uint32_t slot, std::size_t pass, bool end) {
  if (!supported_) return;
  Slot& s = slots_[slot];
  const std::uint32_t query = 2 * static_cast<std::uint32_t>(pass) + (end ? 1 : 0);
  // After everything recorded before it has completed: a pass's time is the interval between the
  // completion of what came before it and its own.
  cmd.writeTimestamp2(vk::PipelineStageFlagBits2::eAllCommands, *s.pool, query);
  s.written |= std::uint64_t{1} << query;
}

void PassTimestamps::collect(std::uint32_t slot) {
  if (!supported_) return;
  Slot& s = slots_[slot];
  if (s.collected) return;
  s.collected = true;
  // Without the wait flag: the slot is finished, so every written query is available; one that is
  // not (it cannot happen on a finished slot) leaves its pass out rather than blocking.
  const auto [result, values] = s.pool.getResults<std::uint64_t>(
      0, queries(), queries() * 2 * sizeof(std::uint64_t), 2 * sizeof(std::uint64_t),
      vk::QueryResultFlagBits::e64 | vk::QueryResultFlagBits::eWithAvailability);
  (void)result;  // eNotReady when a query was never written this frame (a pass that did not run)
  PassTimes t;
  t.frame = s.frame;
  t.ran.assign(count(), false);
  t.ms.assign(count(), 0.0);
  for (std::size_t p = 0; p < count(); ++p) {
    const std::uint32_t a = 2 * static_cast<std::uint32_t>(p), b = a + 1;
    if (!(s.written >> a & 1) || !(s.written >> b & 1) || !values[2 * a + 1] || !values[2 * b + 1]) continue;
    const std::uint64_t ticks = (values[2 * b] - values[2 * a]) & valid_mask_;
    t.ran[p] = true;
    t.ms[p] = static_cast<double>(ticks) * ns_per_tick_ * 1e-6;
  }
  last_ = t;
}

}  // namespace pond::render
