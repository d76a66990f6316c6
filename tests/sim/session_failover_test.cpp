// A GPU failure loses nothing (sim/session.h, sim/solver_journal.h): a stand-in for the GPU solver
// that keeps a host copy now and then and fails at a chosen call; whatever call fails, the session
// goes on on the CPU and ends with the bits of a session that never failed, splashes, drags and
// edits included. Vulkan-free, so it runs in every build; the real GPU solver under the test
// layer's faults is tests/faults.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "core/errors.h"
#include "scene/scene.h"
#include "scene/session_spec.h"
#include "sim/cpu_solver.h"
#include "sim/diagnostics.h"
#include "sim/session.h"

namespace pond::sim {
namespace {

// Counts the calls that may fail, across every solver a session makes; fails the `fail_at`-th.
struct FailurePlan {
  int calls = 0, fail_at = 0;
  void call() {
    if (++calls == fail_at) throw GpuFailure(GpuFailure::Kind::device_lost, "the stand-in device was lost");
  }
};

// A CPU solver that behaves as the GPU solver towards failures: a host copy is taken at the end of
// an advance() that passes `every` steps since the last, and is known to the host only one call
// later (as a submission's copy once a later wait saw it finish); advance() fails half-way.
class FlakySolver final : public Solver {
 public:
  FlakySolver(const WaterModel& model, std::shared_ptr<FailurePlan> plan, std::int64_t every)
      : inner_(model, Backend::scalar, 1), plan_(std::move(plan)), every_(every) {
    plan_->call();
    copy_ = {inner_.state(), 0};
  }
  const WaterModel& model() const override { return inner_.model(); }
  std::int64_t steps_done() const override { return inner_.steps_done(); }
  void advance(std::int64_t steps) override {
    if (pending_) copy_ = *std::exchange(pending_, std::nullopt);
    inner_.advance(steps / 2);
    plan_->call();
    inner_.advance(steps - steps / 2);
    since_ += steps;
    if (since_ >= every_) pending_ = HostSnapshot{inner_.state(), inner_.steps_done()}, since_ = 0;
  }
  void perturb(const PerturbationTable& table) override { inner_.perturb(table); }
  WaterState read_state() override {
    plan_->call();
    return inner_.read_state();
  }
  HostDisplacements displacements() override { return inner_.displacements(); }
  void set_state(const WaterState& state, std::int64_t steps) override {
    plan_->call();
    inner_.set_state(state, steps);
    copy_ = {state, steps};
    pending_.reset();
    since_ = 0;
  }
  std::vector<BodyState> read_bodies() override {
    plan_->call();
    return inner_.read_bodies();
  }
  void set_body_models(std::vector<BodyModel> bodies) override {
    plan_->call();
    inner_.set_body_models(std::move(bodies));
  }
  const HostSnapshot* host_snapshot() override { return &copy_; }
  std::string engine() const override { return "stand-in gpu"; }

 private:
  CpuSolver inner_;
  std::shared_ptr<FailurePlan> plan_;
  std::int64_t every_, since_ = 0;
  HostSnapshot copy_;
  std::optional<HostSnapshot> pending_;
};

scene::Scene busy_scene() {
  return scene::parse_scene(R"({"grid": {"rows": 24, "cols": 31}, "basin": {"floor_depth": 4},
      "constraints": [{"kind": "fixed", "rows": [10, 13], "cols": [20, 23]}],
      "perturbations": [{"step": 3, "row": 6, "col": 8, "radius": 1.5, "amplitude": 0.7},
                        {"step": 40, "row": 18, "col": 12, "radius": 1.0, "amplitude": -0.4, "target": "position"}],
      "bodies": [{"motion": "floating", "radius": 2, "density": 0.5, "position": [6, 1, 16]},
                 {"motion": "floating", "radius": 1.5, "density": 2.0, "position": [25, 2, 5]},
                 {"motion": "kinematic", "radius": 1.5, "path": [[0, 3, 0.3, 3], [60, 12, 0.3, 20]]}],
      "wind": {"ripples": true, "strength": 6}})",
                            "busy");
}

// The same run of steps, splashes, drags and edits; its final hash and the notices it gave.
struct Outcome {
  std::uint64_t hash;
  std::vector<std::string> notices;
  bool on_gpu;
};

Outcome drive(Session& s, std::vector<std::string>& notices) {
  s.advance(7);
  s.splash(Perturbation{.row = 12, .col = 5, .radius = 1.2, .amplitude = 0.9});
  s.advance(13);
  s.drag_body(0, {9.0, 2.0, 12.0}, 5);
  s.advance(9);
  s.release_body(0, {0.05, 0.0, -0.02});
  s.splash(Perturbation{.row = 3, .col = 25, .radius = 1.0, .amplitude = -0.5});
  s.advance(30);
  Physics p = s.water().physics;
  p.damping = 0.08;
  s.set_physics(p);
  s.advance(17);
  s.drag_body(1, {20.0, -1.0, 8.0}, 12);
  s.advance(6);
  s.advance(11);
  const WaterState state = s.state();
  return {state_hash(state, s.model()), notices, s.choice().gpu};
}

TEST(SessionFailover, EveryFailingCallEndsWithTheBitsOfARunThatNeverFailed) {
  std::vector<std::string> none;
  Session reference(scene::session_spec(busy_scene()), SolverChoice{.gpu = false, .backend = Backend::scalar, .threads = 1});
  const std::uint64_t expected = drive(reference, none).hash;

  // Count the calls of a run that never fails, then fail each in turn (and one past the last).
  auto count = std::make_shared<FailurePlan>();
  for (const std::int64_t every : {4, 1000}) {
    SessionSpec spec = scene::session_spec(busy_scene());
    Session counted(std::move(spec), SolverChoice{.gpu = true, .backend = Backend::scalar, .threads = 1},
                    [&](const WaterModel& m) { return std::make_unique<FlakySolver>(m, count, every); });
    std::vector<std::string> notices;
    const Outcome clean = drive(counted, notices);
    ASSERT_EQ(clean.hash, expected) << "the stand-in differs from the CPU without a failure";
    ASSERT_TRUE(clean.on_gpu);
    const int calls = count->calls;
    ASSERT_GE(calls, 15);
    for (int k = 1; k <= calls; ++k) {
      auto plan = std::make_shared<FailurePlan>(FailurePlan{.calls = 0, .fail_at = k});
      std::vector<std::string> told;
      SessionSpec s = scene::session_spec(busy_scene());
      s.notify = [&told](const std::string& text) { told.push_back(text); };
      Session session(std::move(s), SolverChoice{.gpu = true, .backend = Backend::scalar, .threads = 1},
                      [&](const WaterModel& m) { return std::make_unique<FlakySolver>(m, plan, every); });
      const Outcome o = drive(session, told);
      EXPECT_EQ(o.hash, expected) << "failing call " << k << " of " << calls << ", a copy every " << every << " steps";
      EXPECT_FALSE(o.on_gpu) << "call " << k;
      ASSERT_EQ(told.size(), 1u) << "call " << k << ": the failure is told once";
      EXPECT_NE(told[0].find("the stand-in device was lost"), std::string::npos) << told[0];
      EXPECT_NE(told[0].find("going on on the CPU"), std::string::npos) << told[0];
    }
    count->calls = 0;
  }
}

// A failing solver that holds no host copy: nothing to go on from.
class CopylessSolver final : public Solver {
 public:
  explicit CopylessSolver(const WaterModel& model) : inner_(model, Backend::scalar, 1) {}
  const WaterModel& model() const override { return inner_.model(); }
  std::int64_t steps_done() const override { return inner_.steps_done(); }
  void advance(std::int64_t) override { throw GpuFailure(GpuFailure::Kind::out_of_memory, "no memory"); }
  void perturb(const PerturbationTable& t) override { inner_.perturb(t); }
  WaterState read_state() override { return inner_.read_state(); }
  HostDisplacements displacements() override { return inner_.displacements(); }
  void set_state(const WaterState& state, std::int64_t steps) override { inner_.set_state(state, steps); }
  std::vector<BodyState> read_bodies() override { return inner_.read_bodies(); }
  void set_body_models(std::vector<BodyModel> b) override { inner_.set_body_models(std::move(b)); }
  std::string engine() const override { return "copyless"; }

 private:
  CpuSolver inner_;
};

TEST(SessionFailover, WithoutAHostCopyTheFailureReachesTheCaller) {
  Session s(scene::session_spec(busy_scene()), SolverChoice{.gpu = true, .backend = Backend::scalar, .threads = 1},
            [](const WaterModel& m) { return std::make_unique<CopylessSolver>(m); });
  EXPECT_THROW(s.advance(3), GpuFailure);
}

}  // namespace
}  // namespace pond::sim
