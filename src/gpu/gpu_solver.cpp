#include "gpu/gpu_solver.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "core/errors.h"
#include "gpu/float_policy.h"
#include "gpu/gpu_failure.h"

namespace pond::gpu {
namespace {

using BU = vk::BufferUsageFlagBits;
using S = vk::PipelineStageFlagBits2;
using A = vk::AccessFlagBits2;

// The model's kinds (node row * cols + col) with the GPU state's row pitch, packed four per word
// (water_gpu.h); the padding columns are fixed nodes, which keeps their state at +0 (water_step.comp).
std::vector<std::uint32_t> pack_kinds(const sim::WaterModel& model, std::size_t pitch) {
  const auto rows = static_cast<std::size_t>(model.rows), cols = static_cast<std::size_t>(model.cols);
  std::vector<std::uint32_t> words((rows * pitch + 3) / 4 + 1, 0u);  // +1: never empty
  for (std::size_t i = 0; i < rows; ++i)
    for (std::size_t j = 0; j < pitch; ++j) {
      const std::size_t n = i * pitch + j;
      const std::uint32_t kind = j < cols ? std::uint32_t{model.kinds[i * cols + j]} : shared::kNodeFixed;
      words[n / 4] |= kind << (8 * (n % 4));
    }
  return words;
}

// The six component arrays of a state, each `stride` floats, rows `pitch` nodes apart (padding +0).
std::vector<float> to_soa_words(const sim::WaterState& s, std::size_t rows, std::size_t cols, std::size_t pitch,
                                std::size_t stride) {
  std::vector<float> words(stride * kComponents, 0.0f);
  const float* const src[kComponents] = {s.ux.data(), s.uy.data(), s.uz.data(), s.vx.data(), s.vy.data(), s.vz.data()};
  for (unsigned c = 0; c < kComponents; ++c)
    for (std::size_t i = 0; i < rows; ++i)
      std::memcpy(&words[c * stride + i * pitch], src[c] + i * cols, cols * sizeof(float));
  return words;
}

// A table's entries with the state's node numbering (row * pitch + col), appended to `out`.
void append_entries(const sim::PerturbationTable& t, std::size_t cols, std::size_t pitch, std::vector<PerturbEntry>& out) {
  for (std::size_t k = 0; k < t.nodes.size(); ++k)
    out.push_back({static_cast<std::uint32_t>(t.nodes[k] / cols * pitch + t.nodes[k] % cols), t.weights[k]});
}

PerturbPush push_for(const sim::PerturbationTable& t, std::uint32_t first, std::size_t stride) {
  return {.first = first, .count = static_cast<std::uint32_t>(t.nodes.size()), .stride = static_cast<std::uint32_t>(stride),
          .target = t.target == sim::PerturbTarget::velocity ? shared::kPerturbVelocity : shared::kPerturbPosition,
          .mode = t.mode == sim::PerturbMode::add ? shared::kPerturbAdd : shared::kPerturbSet};
}

}  // namespace

GpuSolver::GpuSolver(const Context& ctx, sim::WaterModel model, bool drawn) try
    : ctx_(ctx),
      model_(std::move(model)),
      drawn_(drawn),
      pitch_(row_pitch(static_cast<std::size_t>(model_.cols))),
      stride_(state_stride(static_cast<std::size_t>(model_.rows) * pitch_)) {
  create_buffers();
  map_state_where_host_readable();
  upload_kinds_and_perturbations();
  kernels_ = std::make_unique<WaterKernels>(ctx_, model_, pitch_, stride_,
                                            WaterBuffers{state_, kinds_, table_, normals_, reach_}, SubmissionRing::kSize);
  if (!model_.bodies.empty())
    contact_ = std::make_unique<BodyContact>(ctx_, model_, pitch_, stride_, state_, kernels_->state_r32(),
                                             kernels_->kinds_rgba8(), reach_, steps_per_submit() * model_.substeps,
                                             SubmissionRing::kSize,
                                             model_.math == sim::MathMode::exact && ctx_.denorm_preserve());
  // The host's copies: the displacements unless the state is read in place, and the bodies.
  ring_ = std::make_unique<SubmissionRing>(ctx_, state_[0].mapped ? 0 : 3 * stride_ * sizeof(float),
                                           model_.bodies.size() * sizeof(sim::BodyState));
  if (!state_[0].mapped) readback_ = std::make_unique<DisplacementReadback>(ctx_, pitch_, stride_);
  snapshots_ = std::make_unique<StateSnapshots>(ctx_, model_.rows, model_.cols, pitch_, stride_, model_.bodies.size());
  tile_grid_ = sim::TileGrid(model_.rows, model_.cols);
  set_state(sim::rest_state(model_), 0);
} catch (const vk::SystemError&) {
  rethrow_as_gpu_failure(ctx.device_name(), "while making the GPU solver");
}

GpuSolver::~GpuSolver() {
  if (ring_) ctx_.wait_idle_for_teardown();  // the renderer's frames in flight may read these buffers
}

void GpuSolver::create_buffers() {
  const vk::DeviceSize state_bytes = stride_ * kComponents * sizeof(float);
  const auto state_usage = BU::eStorageBuffer | BU::eUniformTexelBuffer | BU::eTransferSrc | BU::eTransferDst;
  state_[0] = create_buffer(ctx_, state_bytes, state_usage, MemoryUse::device, "water state A");
  state_[1] = create_buffer(ctx_, state_bytes, state_usage, MemoryUse::device, "water state B");
  normals_ = create_buffer(ctx_, std::max<std::size_t>(1, model_.nodes()) * 4 * sizeof(float),
                           BU::eStorageBuffer | BU::eTransferSrc | BU::eVertexBuffer | BU::eUniformTexelBuffer,
                           MemoryUse::device, "water normals");  // texel buffer: render/caustics_pass.h reads it
  // The reach the step shader keeps for the bodies' contact (POND_STEP_BINDING_REACH), from 0; the
  // contact pass sets it back to 0 after every substep.
  reach_ = create_buffer(ctx_, sizeof(std::uint32_t), BU::eStorageBuffer | BU::eTransferDst, MemoryUse::device,
                         "water reach");
  const std::uint32_t zero = 0;
  upload(ctx_, reach_, std::as_bytes(std::span(&zero, 1)));
}

// Where the state's memory is host-readable in place (lavapipe), the state stays mapped and the
// host reads the displacements there instead of a copy of them (displacements()).
void GpuSolver::map_state_where_host_readable() {
  if (!host_readable_in_place(ctx_, state_[0])) return;
  for (Buffer& b : state_) b.mapped = b.memory.mapMemory(0, VK_WHOLE_SIZE);
}

void GpuSolver::upload_kinds_and_perturbations() {
  const std::vector<std::uint32_t> kinds = pack_kinds(model_, pitch_);
  kinds_ = create_buffer(ctx_, kinds.size() * 4, BU::eUniformTexelBuffer | BU::eStorageBuffer | BU::eTransferDst,
                         MemoryUse::device, "water node kinds");
  upload(ctx_, kinds_, std::as_bytes(std::span(kinds)));
  std::vector<PerturbEntry> table;
  for (const sim::PerturbationTable& t : model_.perturbations) {
    table_first_.push_back(static_cast<std::uint32_t>(table.size()));
    append_entries(t, static_cast<std::size_t>(model_.cols), pitch_, table);
  }
  table_ = create_buffer(ctx_, std::max<std::size_t>(1, table.size()) * sizeof(PerturbEntry),
                         BU::eStorageBuffer | BU::eTransferDst, MemoryUse::device, "perturbation table");
  upload(ctx_, table_, std::as_bytes(std::span(table)));
}

std::int64_t GpuSolver::steps_per_submit() const {
  const std::int64_t dispatches_per_step = std::int64_t{std::max(1, model_.substeps)} * (model_.bodies.empty() ? 1 : 2);
  return std::max<std::int64_t>(1, kMaxDispatchesPerSubmit / dispatches_per_step);
}

void GpuSolver::advance(std::int64_t steps) {
  guard_gpu(ctx_, "while stepping the water", [&] {
    if (steps <= 0) return flush_splashes();
    while (steps > 0) {
      const std::int64_t n = std::min(steps, steps_per_submit());
      submit(n, drawn_);
      steps -= n;
    }
  });
}

void GpuSolver::perturb(const sim::PerturbationTable& table) {
  if (table.nodes.empty()) return;
  splash_pushes_.push_back(push_for(table, static_cast<std::uint32_t>(splash_entries_.size()), stride_));
  append_entries(table, static_cast<std::size_t>(model_.cols), pitch_, splash_entries_);
}

void GpuSolver::flush_splashes() {
  if (!splash_pushes_.empty()) submit(0, drawn_);
}

void GpuSolver::submit(std::int64_t steps, bool publish) {
  Submission& s = ring_->begin();
  snapshots_->harvest(ring_->finished_serial());
  const std::uint32_t region = ring_->index_of(s);
  const vk::raii::CommandBuffer& cmd = s.cmd;
  WaterKernels::record_barrier(cmd);  // after every earlier submission's writes (uploads, copies)
  record_splashes(cmd, s);
  if (contact_ && steps > 0) contact_->write_schedule(step_, steps, region);
  const std::int64_t first_step = step_;
  for (std::int64_t k = 0; k < steps; ++k) record_step(cmd, region, first_step);
  if (steps > 0 && snapshots_->due(steps * model_.substeps))  // behind the last step's barrier
    snapshots_->record(cmd, state_[cur_], contact_ ? &contact_->bodies() : nullptr, ring_->next_serial(), step_);
  // The normals (with the tile bounds where tracked) last: of the state every dispatch left.
  if (publish && tiles_) tiles_->record(cmd, cur_, region);
  else if (publish) kernels_->record_normals(cmd, cur_);
  s.published = publish;
  record_copies(cmd, s);
  ring_->submit();
}

Submission& GpuSolver::published() {
  const Submission* last = ring_->last();
  if (!last || !last->published) submit(0, true);
  Submission& done = *ring_->finish_last();
  snapshots_->harvest(ring_->finished_serial());
  return done;
}

const sim::HostSnapshot* GpuSolver::host_snapshot() {
  snapshots_->harvest(ring_->finished_serial());
  return &snapshots_->latest();
}

// The splashes queued since the last submission, from the entry's own table (made larger first if
// they do not fit; the entry is idle).
void GpuSolver::record_splashes(const vk::raii::CommandBuffer& cmd, Submission& s) {
  if (splash_pushes_.empty()) return;
  const vk::DeviceSize bytes = splash_entries_.size() * sizeof(PerturbEntry);
  if (!*s.splashes.buffer || s.splashes.size < bytes) {
    s.splashes = create_buffer(ctx_, std::max<vk::DeviceSize>(bytes, 2 * s.splashes.size), BU::eStorageBuffer,
                               MemoryUse::upload, "splash table " + std::to_string(ring_->index_of(s)));
    kernels_->bind_splash_table(ring_->index_of(s), s.splashes);
  }
  std::memcpy(s.splashes.mapped, splash_entries_.data(), bytes);
  s.splashes.flush(ctx_, bytes);
  for (const PerturbPush& push : splash_pushes_) {
    kernels_->record_perturb(cmd, cur_, static_cast<int>(ring_->index_of(s)), push);
    WaterKernels::record_barrier(cmd);
  }
  splash_entries_.clear();
  splash_pushes_.clear();
}

// One step: its scheduled perturbations, then its substeps, each dispatch behind a barrier, the
// bodies' contact after each substep.
void GpuSolver::record_step(const vk::raii::CommandBuffer& cmd, std::uint32_t region, std::int64_t first_step) {
  while (next_perturbation_ < model_.perturbations.size() && model_.perturbations[next_perturbation_].step == step_) {
    const sim::PerturbationTable& t = model_.perturbations[next_perturbation_];
    const PerturbPush push = push_for(t, table_first_[next_perturbation_], stride_);
    ++next_perturbation_;
    if (push.count == 0) continue;
    kernels_->record_perturb(cmd, cur_, -1, push);
    WaterKernels::record_barrier(cmd);
  }
  for (int s = 0; s < model_.substeps; ++s) {
    kernels_->record_substep(cmd, cur_);
    WaterKernels::record_barrier(cmd);
    cur_ = 1 - cur_;
    if (contact_) {
      contact_->record(cmd, cur_, region, (step_ - first_step) * model_.substeps + s);
      WaterKernels::record_barrier(cmd);
    }
  }
  ++step_;
}

// After the normals: the host's copies of the displacements (unless read in place) and the bodies,
// made visible to the host; and everything the submission wrote before any later submission's
// commands (the renderer's reads, uploads that overwrite the state).
void GpuSolver::record_copies(const vk::raii::CommandBuffer& cmd, const Submission& s) {
  if (s.published && readback_) readback_->record(cmd, state_[cur_], s, ring_->index_of(s));
  if (s.published && contact_)
    cmd.copyBuffer(*contact_->bodies().buffer, *s.bodies.buffer,
                   vk::BufferCopy{.srcOffset = 0, .dstOffset = 0, .size = s.bodies.size});
  const vk::MemoryBarrier2 after{.srcStageMask = S::eComputeShader | S::eTransfer,
                                 .srcAccessMask = A::eShaderWrite | A::eTransferWrite,
                                 .dstStageMask = S::eHost | S::eAllCommands,
                                 .dstAccessMask = A::eHostRead | A::eMemoryRead | A::eMemoryWrite};
  cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &after});
}

void GpuSolver::set_state(const sim::WaterState& state, std::int64_t steps_done) {
  if (state.nodes() != model_.nodes()) throw InternalError("GpuSolver::set_state: the state has the wrong node count");
  if (!contact_ && !state.bodies.empty()) throw InternalError("GpuSolver::set_state: bodies for a model without bodies");
  guard_gpu(ctx_, "while uploading the water's state", [&] { upload_state(state, steps_done); });
}

void GpuSolver::upload_state(const sim::WaterState& state, std::int64_t steps_done) {
  ring_->finish_all();
  snapshots_->set(state, steps_done);
  splash_entries_.clear();
  splash_pushes_.clear();
  const std::vector<float> words = to_soa_words(state, static_cast<std::size_t>(model_.rows),
                                                static_cast<std::size_t>(model_.cols), pitch_, stride_);
  cur_ = 0;
  // Into both buffers: the padding of either is then +0 (the step shader keeps it so).
  for (const Buffer& b : state_) upload(ctx_, b, std::as_bytes(std::span(words)));
  if (contact_) contact_->set_bodies(state.bodies);
  step_ = steps_done;
  next_perturbation_ = 0;
  while (next_perturbation_ < model_.perturbations.size() && model_.perturbations[next_perturbation_].step < step_)
    ++next_perturbation_;
  submit(0, drawn_);  // its normals and copies, when drawn
}

// Copies `src` into a new host-visible buffer after every earlier submission's writes, and makes
// the copy visible to the host.
Buffer GpuSolver::copy_to_host(const Buffer& src, const char* name) {
  flush_splashes();
  Buffer staging = create_buffer(ctx_, src.size, BU::eTransferDst, MemoryUse::readback, name);
  ctx_.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
    WaterKernels::record_barrier(cmd);
    cmd.copyBuffer(*src.buffer, *staging.buffer, vk::BufferCopy{.srcOffset = 0, .dstOffset = 0, .size = src.size});
    const vk::MemoryBarrier2 to_host{.srcStageMask = S::eTransfer, .srcAccessMask = A::eTransferWrite,
                                     .dstStageMask = S::eHost, .dstAccessMask = A::eHostRead};
    cmd.pipelineBarrier2(vk::DependencyInfo{.memoryBarrierCount = 1, .pMemoryBarriers = &to_host});
  });
  staging.invalidate(ctx_);
  return staging;
}

sim::WaterState GpuSolver::read_state() {
  return guard_gpu(ctx_, "while reading the water's state back", [&] { return read_state_now(); });
}

sim::WaterState GpuSolver::read_state_now() {
  const Buffer staging = copy_to_host(state_[cur_], "state readback");
  sim::WaterState s(model_.nodes());
  s.bodies = read_bodies();
  const auto* words = static_cast<const float*>(staging.mapped);
  float* const dst[kComponents] = {s.ux.data(), s.uy.data(), s.uz.data(), s.vx.data(), s.vy.data(), s.vz.data()};
  const auto rows = static_cast<std::size_t>(model_.rows), cols = static_cast<std::size_t>(model_.cols);
  for (unsigned c = 0; c < kComponents; ++c)  // drops the padding: rows * cols, as sim::WaterState
    for (std::size_t i = 0; i < rows; ++i)
      std::memcpy(dst[c] + i * cols, words + c * stride_ + i * pitch_, cols * sizeof(float));
  return s;
}

sim::HostDisplacements GpuSolver::displacements() {
  Submission& s = guard_gpu(ctx_, "while waiting for the water's step", [&]() -> Submission& { return published(); });
  if (readback_) return readback_->host(s, ring_->index_of(s));
  const float* u = static_cast<const float*>(state_[cur_].mapped);  // read in place (lavapipe)
  return {u, u + stride_, u + 2 * stride_, pitch_};
}

namespace {

// `w` cut to a rows x cols grid (empty: no rows or no columns left).
core::GridWindow within(const core::GridWindow& w, int rows, int cols) {
  const int r0 = std::max(0, w.row0), c0 = std::max(0, w.col0);
  const int r1 = std::min(rows, w.row0 + w.rows), c1 = std::min(cols, w.col0 + w.cols);
  return r0 < r1 && c0 < c1 ? core::GridWindow{r0, c0, r1 - r0, c1 - c0} : core::GridWindow{};
}

// The same for each of `windows`, the empty ones left out.
std::vector<core::GridWindow> within(std::span<const core::GridWindow> windows, int rows, int cols) {
  std::vector<core::GridWindow> out;
  for (const core::GridWindow& w : windows)
    if (const core::GridWindow in = within(w, rows, cols); in.rows > 0) out.push_back(in);
  return out;
}

}  // namespace

void GpuSolver::keep_on_host(std::optional<std::vector<core::GridWindow>> windows) {
  if (!readback_) return;
  if (!windows) return readback_->keep(std::nullopt);
  readback_->keep(core::NodeRuns(within(*windows, model_.rows, model_.cols)));
}

bool GpuSolver::holds_on_host(const core::GridWindow& w) {
  if (!readback_) return true;
  const core::GridWindow in = within(w, model_.rows, model_.cols);
  Submission& s = guard_gpu(ctx_, "while waiting for the water's step", [&]() -> Submission& { return published(); });
  return in.rows == 0 || readback_->holds(s, ring_->index_of(s), in);
}

void GpuSolver::bring_to_host(std::span<const core::GridWindow> windows) {
  if (!readback_) return;
  guard_gpu(ctx_, "while reading the water's nodes back", [&] {
    Submission& s = published();
    readback_->bring(s, ring_->index_of(s), state_[cur_], within(windows, model_.rows, model_.cols));
  });
}

std::vector<sim::BodyState> GpuSolver::read_bodies() {
  if (!contact_) return {};
  Submission* s = &guard_gpu(ctx_, "while reading the bodies back", [&]() -> Submission& { return published(); });
  if (!s->bodies_seen) s->bodies.invalidate(ctx_);
  s->bodies_seen = true;
  std::vector<sim::BodyState> out(model_.bodies.size());
  std::memcpy(out.data(), s->bodies.mapped, out.size() * sizeof(sim::BodyState));
  return out;
}

sim::Normals GpuSolver::normals() {
  const Buffer staging = guard_gpu(ctx_, "while reading the normals back", [&] {
    published();  // the normals of the current state
    return copy_to_host(normals_, "normals readback");
  });
  sim::Normals n;
  const auto* v = static_cast<const float*>(staging.mapped);
  for (std::size_t k = 0; k < model_.nodes(); ++k) {
    n.x.push_back(v[4 * k]);
    n.y.push_back(v[4 * k + 1]);
    n.z.push_back(v[4 * k + 2]);
  }
  return n;
}

void GpuSolver::track_tile_bounds(bool on) {
  guard_gpu(ctx_, "while setting up the tile bounds", [&] { track_tiles(on); });
}

void GpuSolver::track_tiles(bool on) {
  if (on == static_cast<bool>(tiles_)) return;
  if (!on) {
    ctx_.queue().waitIdle();  // a renderer's frames in flight may read the bounds
    tiles_.reset();
    return;
  }
  tiles_ = std::make_unique<TileKernels>(ctx_, model_, *kernels_, normals_,
                                         model_.math == sim::MathMode::exact && ctx_.denorm_preserve(),
                                         SubmissionRing::kSize);
  submit(0, true);  // the current state's bounds (and its splashes)
}

std::span<const sim::TileBounds> GpuSolver::tile_bounds() {
  if (!tiles_) return {};
  Submission& s = guard_gpu(ctx_, "while waiting for the water's step", [&]() -> Submission& { return published(); });
  return tiles_->host_bounds(ring_->index_of(s));
}

void GpuSolver::set_body_models(std::vector<sim::BodyModel> bodies) {
  if (bodies.size() != model_.bodies.size()) throw InternalError("set_body_models: another number of bodies");
  model_.bodies = std::move(bodies);
  if (contact_) guard_gpu(ctx_, "while uploading the bodies", [&] { contact_->upload_constants(); });
}

std::string GpuSolver::identity() const {
  return model_.math == sim::MathMode::exact ? identity_line(ctx_) : std::string();
}

}  // namespace pond::gpu
