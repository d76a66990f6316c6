#pragma once
// The GPU solver's state copied to the host every so often, so that a CPU solver can go on from it
// with the same bits when the device is lost (sim/solver_journal.h; docs/gpu.md, the CPU twin).
// A submission that ends at least kSubsteps substeps after the last copy also copies the state and
// the bodies into a readback buffer; once that submission is known finished (the solver waited for
// it or for a later one, as it does anyway), the host takes the copy into its own memory, which a
// lost device cannot take away. No wait of its own: the copy costs the GPU a copy of 24 bytes a
// node every kSubsteps substeps, the host the same in memcpy.
#include <cstdint>

#include "gpu/buffer.h"
#include "gpu/context.h"
#include "sim/solver.h"

namespace pond::gpu {

class StateSnapshots {
 public:
  static constexpr std::int64_t kSubsteps = 256;  // the default interval

  // For a state of rows x cols nodes laid out as the GPU solver's (rows `pitch` nodes apart, the
  // components `stride` floats apart) with `bodies` bodies.
  StateSnapshots(const Context& ctx, int rows, int cols, std::size_t pitch, std::size_t stride, std::size_t bodies);

  // The host holds `state` at `step` (the solver's set_state): the newest copy, no GPU copy pending.
  void set(const sim::WaterState& state, std::int64_t step);
  // Counts the substeps of a submission being recorded; true when it should carry a copy.
  bool due(std::int64_t substeps);
  // Substeps between copies (0: none, for benchmarks measuring what the copies cost).
  void set_interval(std::int64_t substeps) { interval_ = substeps; }
  // Records the copy of `state` (and `bodies`, if any) at `step` into the submission with serial
  // `serial` (SubmissionRing::next_serial()), after its last step's barrier.
  void record(const vk::raii::CommandBuffer& cmd, const Buffer& state, const Buffer* bodies, std::uint64_t serial,
              std::int64_t step);
  // Takes the pending copy if its submission is finished (`finished`: SubmissionRing::finished_serial()).
  void harvest(std::uint64_t finished);
  const sim::HostSnapshot& latest() const { return latest_; }

 private:
  const Context& ctx_;
  int rows_, cols_;
  std::size_t pitch_, stride_, bodies_;
  Buffer readback_;  // the state's six components (stride floats each), then the bodies
  sim::HostSnapshot latest_;
  std::uint64_t pending_serial_ = 0;  // 0: no copy pending
  std::int64_t pending_step_ = 0;
  std::int64_t since_ = 0;  // substeps recorded since the last copy
  std::int64_t interval_ = kSubsteps;
};

}  // namespace pond::gpu
