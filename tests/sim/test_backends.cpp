// Every backend and every thread count gives the same bits, and the golden hash of the default
// scene, shared by all of them (and by the IA-32 build and the GPU), is pinned here.
#include <gtest/gtest.h>

#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>

#include "core/cpu_features_mask.h"
#include "core/errors.h"
#include "shared/exact_math.h"
#include "sim/backends.h"
#include "sim/diagnostics.h"
#include "test_util.h"

namespace pond::sim {
namespace {

using scene::load_scene;
using scene::parse_scene;
using scene::Scene;

// The default scene after 1,000 steps, exact math. Changing the model's arithmetic changes it;
// then every backend, the IA-32 build and the GPU must agree on the new value.
constexpr std::uint64_t kGoldenDefaultScene1000 = 0x338fc857b8648871ull;

std::vector<Backend> available() { return test::available_backends(); }

std::string hex(std::uint64_t v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%016" PRIx64, v);
  return buf;
}

TEST(Backends, GoldenHashOfTheDefaultScene) {
  const WaterModel m = build_model(load_scene(""));
  for (Backend b : available())
    for (int threads : {1, 2}) {
      CpuSolver solver(m, b, threads);
      solver.advance(1000);
      const std::uint64_t h = state_hash(solver.state(), m);
      EXPECT_EQ(h, kGoldenDefaultScene1000)
          << backend_name(b) << " x " << threads << " threads: actual hash " << hex(h);
    }
}

struct MatrixCase {
  const char* name;
  Scene scene;
  int steps;
};

std::vector<MatrixCase> matrix() {
  using test::grid_scene;
  using test::splash;
  std::vector<MatrixCase> cases;
  {
    Scene s = grid_scene(50, 50);
    s.perturbations.push_back(splash(25, 25, 2, 1));
    cases.push_back({"paper 50x50", s, 400});
  }
  {
    Scene s = grid_scene(41, 67, NodeKind::vertical);
    s.constraints.push_back({NodeKind::fixed, 10, 15, 20, 30});
    s.constraints.push_back({NodeKind::vertical, 30, 35, 5, 8});
    s.perturbations.push_back(splash(20, 40, 3, 2, 0, PerturbTarget::velocity, PerturbMode::add));
    s.perturbations.push_back(splash(5.5, 10.25, 1.5, 0.5, 37, PerturbTarget::position, PerturbMode::add));
    s.perturbations.push_back(splash(30, 60, 2, -1, 80, PerturbTarget::velocity, PerturbMode::set));
    s.perturbations.push_back(splash(12, 3, 2, 0.3, 150, PerturbTarget::position, PerturbMode::set));
    cases.push_back({"41x67 constraints, every perturbation", s, 300});
  }
  {
    Scene s = grid_scene(3, 97, NodeKind::free);
    s.perturbations.push_back(splash(1, 50, 4, 1));
    cases.push_back({"3x97 free border", s, 300});
  }
  {
    Scene s = grid_scene(2, 2, NodeKind::free);
    s.perturbations.push_back(splash(0.5, 0.5, 1, 0.2, 0, PerturbTarget::position));
    cases.push_back({"2x2", s, 300});
  }
  {
    Scene s = grid_scene(17, 9, NodeKind::free);
    s.physics.rest_ratio = 0.9;
    s.physics.substeps = 3;
    s.perturbations.push_back(splash(8, 4, 2, 1));
    cases.push_back({"17x9 pre-tension, substeps", s, 200});
  }
  {
    // Wider than one column block (1024) of the kernel, with a splash on the block boundary.
    Scene s = grid_scene(24, 1100);
    s.perturbations.push_back(splash(12, 1023.5, 3, 1.5));
    s.perturbations.push_back(splash(20, 511.5, 3, 1.5));
    s.perturbations.push_back(splash(5, 1050, 2, 1, 10));
    cases.push_back({"24x1100 across column blocks", s, 120});
  }
  {
    Scene s = grid_scene(200, 90);  // tall: several row parts for threads
    s.constraints.push_back({NodeKind::fixed, 99, 101, 0, 89});  // a wall at a part boundary
    s.perturbations.push_back(splash(100, 45, 4, 2));
    s.perturbations.push_back(splash(150, 20, 2, 1, 30));
    cases.push_back({"200x90 wall", s, 150});
  }
  return cases;
}

TEST(Backends, AllBackendsAndThreadCountsAgreeBitForBit) {
  for (const MatrixCase& c : matrix())
    for (MathMode math : {MathMode::exact, MathMode::fast}) {
      const WaterModel m = build_model(c.scene, math);
      CpuSolver reference(m, Backend::scalar, 1);
      reference.advance(c.steps);
      const std::uint64_t want = state_hash(reference.state(), m);
      for (Backend b : available())
        for (int threads : {1, 2, 3}) {
          CpuSolver solver(m, b, threads);
          solver.advance(c.steps);
          EXPECT_EQ(state_hash(solver.state(), m), want)
              << c.name << ", " << backend_name(b) << " x " << threads << " threads, "
              << (math == MathMode::exact ? "exact" : "fast");
        }
    }
}

TEST(Backends, EveryRowWidthAgreesBitForBit) {
  // The kernel covers a row with full-width chunks, then a last chunk that may be narrower (half
  // width) or overlap the one before, and takes the one spring without a right neighbour from that
  // chunk or on its own: every remainder of every backend's width, and both sides of a column
  // block (1024), against the scalar backend.
  std::vector<int> widths;
  for (int c = 2; c <= 70; ++c) widths.push_back(c);
  for (int c : {95, 96, 97, 127, 128, 129, 511, 512, 513, 1017, 1023, 1024, 1025, 1026, 1032, 1039,
                1040, 1041, 2100})
    widths.push_back(c);
  for (int cols : widths) {
    Scene s = test::grid_scene(5, cols, NodeKind::free);
    s.perturbations.push_back(test::splash(2, 0.4 * cols, 1.5, 1));
    s.perturbations.push_back(test::splash(1, cols - 1.5, 1, -0.5, 3));
    const WaterModel m = build_model(s);
    CpuSolver reference(m, Backend::scalar, 1);
    reference.advance(12);
    const std::uint64_t want = state_hash(reference.state(), m);
    for (Backend b : available()) {
      CpuSolver solver(m, b, 1);
      solver.advance(12);
      EXPECT_EQ(state_hash(solver.state(), m), want) << "5x" << cols << ", " << backend_name(b);
    }
  }
}

TEST(Backends, ThreadPartsReallySplitTheRows) {
  // Large enough for 2 parts: threads are used, so the equality above is not vacuous.
  const WaterModel m = build_model(test::grid_scene(256, 256));
  EXPECT_EQ(CpuSolver(m, Backend::scalar, 2).threads(), 2);
}

TEST(Backends, FastMathStaysCloseToExact) {
  Scene s = test::grid_scene(50, 50);
  s.perturbations.push_back(test::splash(25, 25, 2, 1));
  const WaterState exact = test::run(s, 200, Backend::scalar, 1, MathMode::exact);
  const WaterState fast = test::run(s, 200, Backend::scalar, 1, MathMode::fast);
  double worst = 0, peak = 0;
  for (std::size_t n = 0; n < exact.nodes(); ++n) {
    worst = std::max(worst, double(std::fabs(exact.uy[n] - fast.uy[n])));
    peak = std::max(peak, double(std::fabs(exact.uy[n])));
  }
  std::printf("fast vs exact after 200 steps: max |dy| %.3g of peak %.3g\n", worst, peak);
  EXPECT_LT(worst, 1e-3 * peak);
}

using test::CpuFeaturesMask;

std::string forcing_error(Backend b) {
  try {
    CpuSolver(build_model(test::grid_scene(4, 4)), b, 1);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

// A backend this CPU lacks, on any CPU: AVX2 masked out (and AVX-512F with it, as on a real CPU
// without AVX2). Forcing it is an InputError naming it; auto falls back to SSE; SSE still runs.
TEST(Backends, ForcingAMaskedOutBackendFailsClearly) {
  if (!compiled_in(Backend::sse)) GTEST_SKIP() << "an aarch64 build: no x86 backends (NEON's below)";
  const bool in_build = step_rows_avx2(shared::kRsqrtStepsExact, false, false) != nullptr;  // not in IA-32 builds
  const CpuFeaturesMask mask("avx2");
  EXPECT_FALSE(cpu_supports(Backend::avx2));
  EXPECT_FALSE(cpu_supports(Backend::avx512));
  EXPECT_TRUE(cpu_supports(Backend::sse));
  EXPECT_EQ(best_backend(), Backend::sse);
  const std::string what = forcing_error(Backend::avx2);
  EXPECT_NE(what.find(in_build ? "solver avx2: AVX2 is masked out by POND_CPU_FEATURES_MASK"
                               : "solver avx2 is not in this build"),
            std::string::npos)
      << what;
  EXPECT_NE(forcing_error(Backend::avx512).find("solver avx512"), std::string::npos);
  EXPECT_NO_THROW(CpuSolver(build_model(test::grid_scene(4, 4)), Backend::sse, 1));
}

TEST(Backends, MaskingSse2LeavesScalar) {
  if (!compiled_in(Backend::sse)) GTEST_SKIP() << "an aarch64 build: no x86 backends (NEON's below)";
  const CpuFeaturesMask mask("avx512f,sse2");
  EXPECT_EQ(best_backend(), Backend::scalar);
  EXPECT_EQ(forcing_error(Backend::sse), "solver sse: SSE2 is masked out by POND_CPU_FEATURES_MASK");
}

// NEON: auto's choice on aarch64, where every CPU has it; masked out, forcing it is an InputError
// naming it and auto falls back to scalar. In an x86 build it is not in the build, and the x86
// features' mask does not touch it (nor neon's theirs).
TEST(Backends, NeonIsAutosChoiceOnlyInAnAarch64Build) {
  const bool aarch64 = compiled_in(Backend::neon);
  EXPECT_EQ(aarch64, !compiled_in(Backend::sse));
  if (aarch64) {
    EXPECT_EQ(best_backend(), Backend::neon);
    {
      const CpuFeaturesMask mask("avx2,sse2");  // another architecture's: hides nothing here
      EXPECT_EQ(best_backend(), Backend::neon);
    }
    const CpuFeaturesMask mask("neon");
    EXPECT_EQ(best_backend(), Backend::scalar);
    EXPECT_EQ(forcing_error(Backend::neon), "solver neon: NEON is masked out by POND_CPU_FEATURES_MASK");
  } else {
    const std::string what = forcing_error(Backend::neon);
    EXPECT_NE(what.find("solver neon is not in this build (its CPU solvers: scalar sse"), std::string::npos) << what;
    const Backend best = best_backend();
    const CpuFeaturesMask mask("neon");
    EXPECT_EQ(best_backend(), best);
  }
}

TEST(Backends, MaskHidesOnlyWhatItNames) {
  const bool avx2 = cpu_supports(Backend::avx2);
  const Backend best = best_backend();
  {
    const CpuFeaturesMask mask("avx512f");
    EXPECT_FALSE(cpu_supports(Backend::avx512));
    EXPECT_EQ(cpu_supports(Backend::avx2), avx2);
  }
  {
    const CpuFeaturesMask mask("");
    EXPECT_EQ(best_backend(), best);
  }
  const CpuFeaturesMask mask("avx2,mmx");
  EXPECT_THROW(best_backend(), InputError);  // a typo is an error, not an empty mask
}

}  // namespace
}  // namespace pond::sim
