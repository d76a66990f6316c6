// `pond check`'s built-in cases are what they say they are (on the CPU: no GPU needed): every one
// parses and runs; the denormal case's waves do pass through the denormal range, so a device that
// flushes denormals gives other bits (the CPU with FTZ and DAZ set stands in for one); the odd
// width is not a multiple of 4.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#if defined(__x86_64__) || defined(__i386__)
#include <xmmintrin.h>
#endif

#include "app/check_cases.h"
#include "scene/scene.h"
#include "sim/cpu_solver.h"
#include "sim/diagnostics.h"

namespace pond::app {
namespace {

sim::WaterModel model_of(const CheckCase& c) {
  return sim::build_model(check_scene(c));
}

const CheckCase& find(const std::string& name) {
  for (const CheckCase& c : check_cases())
    if (name == c.name) return c;
  throw std::runtime_error("no check case " + name);
}

std::size_t denormals(const sim::WaterState& s) {
  std::size_t n = 0;
  for (const auto* a : {&s.ux, &s.uy, &s.uz, &s.vx, &s.vy, &s.vz})
    for (float x : *a) n += std::fpclassify(x) == FP_SUBNORMAL;
  return n;
}

// The CPU flushes denormal inputs and results to zero while one lives: a device that flushes them.
// x86: MXCSR's FTZ and DAZ; aarch64: FPCR's FZ (both, for single and double precision).
class FlushingDenormals {
 public:
#if defined(__x86_64__) || defined(__i386__)
  FlushingDenormals() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | 0x8040u); }
  ~FlushingDenormals() { _mm_setcsr(saved_); }

 private:
  unsigned saved_;
#elif defined(__aarch64__)
  FlushingDenormals() {
    asm volatile("mrs %0, fpcr" : "=r"(saved_));
    asm volatile("msr fpcr, %0" : : "r"(saved_ | (std::uint64_t{1} << 24)));
  }
  ~FlushingDenormals() { asm volatile("msr fpcr, %0" : : "r"(saved_)); }

 private:
  std::uint64_t saved_ = 0;
#endif
};

TEST(CheckCases, EveryCaseRunsItsLength) {
  for (const CheckCase& c : check_cases()) {
    sim::CpuSolver solver(model_of(c), sim::Backend::scalar, 1);
    EXPECT_NO_THROW(solver.advance(c.steps)) << c.name;
    EXPECT_FALSE(sim::first_blown_up_node(solver.state())) << c.name;
  }
}

TEST(CheckCases, TheDenormalCaseDecaysThroughTheDenormalsAndFlushingChangesIt) {
  const CheckCase& c = find("denormal_decay");
  sim::CpuSolver solver(model_of(c), sim::Backend::scalar, 1);
  std::size_t most = 0;
  for (std::int64_t done = 0; done < c.steps; done += 100) {
    solver.advance(100);
    most = std::max(most, denormals(solver.state()));
  }
  EXPECT_GT(most, 100u) << "the waves never reached the denormal range";

  std::uint64_t flushed_hash = 0;
  {
    const FlushingDenormals flushing_cpu;
    sim::CpuSolver flushing(model_of(c), sim::Backend::scalar, 1);
    flushing.advance(c.steps);
    flushed_hash = sim::state_hash(flushing.state(), flushing.model());
  }
  EXPECT_NE(flushed_hash, sim::state_hash(solver.state(), solver.model()));
}

TEST(CheckCases, TheOddWidthIsPadded) { EXPECT_NE(model_of(find("odd_width_17x33")).cols % 4, 0); }

// The bodies case exercises the contact: the floating balls end up carried by the water (resting
// in it, not fallen through or still where they started) and the sphere at the end of its path.
TEST(CheckCases, TheBodiesCaseTouchesTheWater) {
  const CheckCase& c = find("bodies");
  sim::CpuSolver solver(model_of(c), sim::Backend::scalar, 1);
  solver.advance(c.steps);
  const auto& b = solver.state().bodies;
  ASSERT_EQ(b.size(), 3u);
  EXPECT_FLOAT_EQ(b[0].x, 40.0f);
  for (std::size_t k = 1; k < 3; ++k) {
    EXPECT_LT(b[k].y, 2.5f) << k;
    EXPECT_GT(b[k].y, -3.0f) << k;
  }
  EXPECT_FALSE(sim::first_blown_up_body(solver.state()));
}

// The floating case: the balls float apart after their collision, one rests on the island, the
// dense one on the floor.
TEST(CheckCases, TheFloatingCaseCollidesFloatsAndSinks) {
  const CheckCase& c = find("floating");
  const sim::WaterModel model = model_of(c);
  sim::CpuSolver solver(model, sim::Backend::scalar, 1);
  solver.advance(c.steps);
  const auto& b = solver.state().bodies;
  ASSERT_EQ(b.size(), 5u);
  const float dx = b[1].x - b[0].x, dy = b[1].y - b[0].y, dz = b[1].z - b[0].z;
  EXPECT_GT(std::sqrt(dx * dx + dy * dy + dz * dz), 4.5f - 0.02f) << "no more than 1 % overlap";
  EXPECT_LT(b[0].x, 26.0f) << "the head-on pair bounced";
  EXPECT_NEAR(b[2].y, 1.0f + 1.5f, 0.05f) << "on the island";
  EXPECT_NEAR(b[3].y, -3.0f + 1.5f, 0.05f) << "on the floor";
  EXPECT_FALSE(sim::first_blown_up_body(solver.state()));
}

}  // namespace
}  // namespace pond::app
