#pragma once
// The node budgets' loops (camera_budget.h: node_budgets), built twice: by camera_budget.cpp for
// the target's baseline (SSE2, NEON) and on x86-64 by camera_budget_avx2.cpp with AVX2's flags
// (pond_isa_sources). The compiler vectorizes them, and every lane does a node's operations in the
// same order, so both copies write the same bits. In the file's inline namespace
// (sim/isa_namespace.h): each file keeps its own copy, not the linker's pick.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "lod/camera_budget.h"
#include "sim/isa_namespace.h"

namespace pond::lod {

#if POND_LOD_AVX2  // x86-64 builds
void node_budgets_avx2(const NodePositions& p, const BudgetTerms& t, float* budget, bool all_in_view);  // camera_budget_avx2.cpp
#endif

inline namespace POND_ISA {

inline void budget_loop(const NodePositions& p, const BudgetTerms& t, float* budget, bool all_in_view) {
  const ViewBasis& b = t.basis;
  const float delta = static_cast<float>(t.delta);
  const float tx = static_cast<float>(t.tan_x), ty = static_cast<float>(t.tan_y);
  const float cone2 = tx * tx + ty * ty;
  const float per_depth = static_cast<float>(t.per_depth);
  const float infinite = std::numeric_limits<float>::infinity();
  const float ex = float(b.eye[0]), ey = float(b.eye[1]), ez = float(b.eye[2]);
  const float f0 = float(b.forward[0]), f1 = float(b.forward[1]), f2 = float(b.forward[2]);
  const float r0 = float(b.right[0]), r1 = float(b.right[1]), r2 = float(b.right[2]);
  const float u0 = float(b.up[0]), u1 = float(b.up[1]), u2 = float(b.up[2]);
  const float* px = p.x;
  const float* py = p.y;
  const float* pz = p.z;
  const std::size_t n = p.nodes();
  // Branch-free bodies (& rather than &&, selects) so the compiler vectorizes; the cone apart.
  // A node counts as in view when it might be (widened by delta); its budget uses the lowest
  // depth it might have, clamped at 0.
  if (all_in_view) {  // the budgets as below, operation for operation, without the frustum's tests
    for (std::size_t k = 0; k < n; ++k) {
      const float dx = px[k] - ex, dy = py[k] - ey, dz = pz[k] - ez;
      const float depth = dx * f0 + dy * f1 + dz * f2;
      const float low = depth - delta;
      budget[k] = per_depth * std::max(low, 0.0f);
    }
    return;
  }
  if (b.cone) {
    for (std::size_t k = 0; k < n; ++k) {
      const float dx = px[k] - ex, dy = py[k] - ey, dz = pz[k] - ez;
      const float depth = dx * f0 + dy * f1 + dz * f2;
      const float sx = std::abs(dx * r0 + dy * r1 + dz * r2) - delta;
      const float sy = std::abs(dx * u0 + dy * u1 + dz * u2) - delta;
      const float far = depth + delta;
      const float sxp = std::max(sx, 0.0f), syp = std::max(sy, 0.0f);
      const float sx2 = sxp * sxp, sy2 = syp * syp;
      const bool in_view = (far > 0) & (sx2 + sy2 <= cone2 * far * far);
      const float low = depth - delta;
      const float own = per_depth * std::max(low, 0.0f);
      budget[k] = in_view ? own : infinite;
    }
    return;
  }
  for (std::size_t k = 0; k < n; ++k) {
    const float dx = px[k] - ex, dy = py[k] - ey, dz = pz[k] - ez;
    const float depth = dx * f0 + dy * f1 + dz * f2;
    const float sx = dx * r0 + dy * r1 + dz * r2, sy = dx * u0 + dy * u1 + dz * u2;
    const float far = depth + delta;
    // `&` on purpose: all three tests are cheap, and without branches the loop vectorizes.
    const bool in_view = static_cast<bool>(static_cast<int>(far > 0) & static_cast<int>(std::abs(sx) <= tx * far + delta) &
                                           static_cast<int>(std::abs(sy) <= ty * far + delta));
    const float low = depth - delta;
    const float own = per_depth * std::max(low, 0.0f);
    budget[k] = in_view ? own : infinite;
  }
}

}  // namespace POND_ISA
}  // namespace pond::lod
