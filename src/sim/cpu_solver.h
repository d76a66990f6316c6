#pragma once
// The CPU reference solver: advances a WaterState step by step (each step = the model's substeps),
// applying each perturbation just before the integration of its step, on one backend and a
// number of threads. The result does not depend on either (same bits).
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "sim/aligned_buffer.h"
#include "sim/backends.h"
#include "sim/model.h"
#include "sim/row_threads.h"
#include "sim/solver.h"
#include "sim/state.h"
#include "sim/tile_bounds.h"

namespace pond::sim {

class CpuSolver final : public Solver {
 public:
  // threads <= 0: all cores. Throws InputError when the backend is unavailable.
  CpuSolver(WaterModel model, Backend backend, int threads = 0);

  const WaterModel& model() const override { return model_; }
  Backend backend() const { return backend_; }
  int threads() const { return threads_->size(); }
  std::int64_t steps_done() const override { return step_; }
  const WaterState& state() const { return cur_; }
  WaterState read_state() override { return cur_; }
  // Replaces the state and the step counter (e.g. when switching solvers).
  void set_state(const WaterState& state, std::int64_t steps_done) override;
  std::string engine() const override;
  void set_body_models(std::vector<BodyModel> bodies) override;
  std::vector<BodyState> read_bodies() override { return cur_.bodies; }
  void perturb(const PerturbationTable& table) override;
  HostDisplacements displacements() override {
    return {cur_.ux.data(), cur_.uy.data(), cur_.uz.data(), static_cast<std::size_t>(model_.cols)};
  }

  // Advances `steps` steps. Throws InputError naming the step when the state becomes non-finite.
  void advance(std::int64_t steps) override;

  // Whether to keep the tile bounds (shared/tile_bounds.h) of the current state: the last substep
  // of each advance() emits them from its kernel (those before it leave no state anyone reads; the
  // GPU solver, too, makes them once a frame, in its normals dispatch), and its contact and perturb()
  // keep them true. Off at first, so that nothing pays for them while no one reads them; turning it
  // on computes them from the state.
  void track_tile_bounds(bool on) override;
  // The current state's tile bounds, tile (a, b) at b * tiles_x + a; empty while not tracked.
  std::span<const TileBounds> tile_bounds() override { return tile_bounds_; }
  const TileGrid& tile_grid() const { return tile_grid_; }

 private:
  // One substep, then the bodies' contact (sim/contact.h); `tiles`: emitting the tile bounds.
  void substep(int substep_index, bool tiles);
  std::pair<int, int> part_rows(int part) const;  // the node rows [r0, r1) of a part
  void refresh_tiles(const NodeRect& moved);  // if tracked
  WaterModel model_;
  Backend backend_;
  StepRowsFn kernel_;       // without the tile bounds
  StepRowsFn tile_kernel_;  // emitting them (the last substep of an advance() while tracked)
  std::unique_ptr<RowThreads> threads_;
  int parts_ = 1;
  WaterState cur_, next_;
  std::vector<AlignedBuffer<float>> scratch_;  // spring rows, one per part
  std::vector<float> checks_;                  // blow-up check of each part
  std::vector<float> reaches_;                 // largest |ux|, |uz| of each part (with bodies)
  TileGrid tile_grid_;
  std::vector<TileBounds> tile_bounds_;          // empty while not tracked
  std::vector<AlignedBuffer<float>> tile_columns_;  // per part: TileSink::columns
  std::vector<std::vector<TileBounds>> tile_rows_;  // per part: its partial tile rows
  std::vector<TileRowSpan> tile_spans_;             // per part: which tile rows those are
  std::vector<NodeRect> moved_;                     // by the contact, this substep
  std::size_t next_perturbation_ = 0;
  std::int64_t step_ = 0;
};

}  // namespace pond::sim
