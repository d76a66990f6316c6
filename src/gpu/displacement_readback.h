#pragma once
// The host's copy of the GPU solver's displacements where the state is not host-readable in place
// (a discrete GPU). Each publishing submission copies all of ux | uy | uz, or, once the host says
// which nodes it reads (keep(): a renderer's LOD, its blocks), only those, packed by one dispatch
// (water_gather.comp: a copy command would need a region per run, thousands), which the host then
// unpacks into an array of the state's own layout. Nodes it lacks are brought in one dispatch and
// one wait (bring()).
#include <array>
#include <optional>
#include <span>
#include <vector>

#include "core/node_runs.h"
#include "gpu/buffer.h"
#include "gpu/compute_pipeline.h"
#include "gpu/context.h"
#include "gpu/submission_ring.h"
#include "sim/solver.h"

namespace pond::gpu {

class DisplacementReadback {
 public:
  // The state's layout: rows of `pitch` nodes, the components `stride` floats apart.
  DisplacementReadback(const Context& ctx, std::size_t pitch, std::size_t stride);

  // What later submissions copy: every node (nullopt) or the nodes of `runs`.
  void keep(std::optional<core::NodeRuns> runs) { keep_ = std::move(runs); }
  // Records submission s's copy of `state` (ux | uy | uz first) into its readback buffer.
  void record(const vk::raii::CommandBuffer& cmd, const Buffer& state, const Submission& s, std::uint32_t index);
  // Submission s (finished, ring index `index`) as the host holds it: unpacked on first call.
  sim::HostDisplacements host(Submission& s, std::uint32_t index);
  // Whether host() of s holds every node of w.
  bool holds(Submission& s, std::uint32_t index, const core::GridWindow& w);
  // Copies the nodes of `windows` that host() of s lacks from `state` (s's state, unchanged since)
  // and waits for them.
  void bring(Submission& s, std::uint32_t index, const Buffer& state, std::span<const core::GridWindow> windows);

 private:
  // Records the packing of `runs` of `state` into `packed` (component by component, runs in order)
  // with runs buffer and descriptor set `slot` (idle).
  void record_gather(const vk::raii::CommandBuffer& cmd, const Buffer& state, const Buffer& packed,
                     const core::NodeRuns& runs, std::uint32_t slot);
  void unpack(const core::NodeRuns& runs, const float* packed);

  const Context& ctx_;
  std::size_t pitch_, stride_;
  std::optional<core::NodeRuns> keep_;
  std::array<std::optional<core::NodeRuns>, SubmissionRing::kSize> copied_;  // per ring entry
  std::vector<float> host_;  // the unpacked nodes, in the state's layout
  core::NodeRuns held_;      // which of host_ are current
  Buffer fetched_;           // bring()'s readback, grown when needed
  ComputePipeline gather_;
  vk::raii::DescriptorPool pool_ = nullptr;
  // Per ring entry, then bring()'s: the runs' list (grown when needed) and the gather's set.
  std::array<Buffer, SubmissionRing::kSize + 1> runs_;
  std::vector<vk::raii::DescriptorSet> sets_;
};

}  // namespace pond::gpu
