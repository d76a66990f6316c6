#pragma once
// The wide-float table every CPU of the build's target has, which code without a run-time choice
// of backend uses (the tile bounds of the scalar backend, the LOD's baseline scans and copies):
// SSE2 on x86 (x86-64, and the IA-32 build's -msse2), NEON on aarch64.
#include "sim/isa_namespace.h"

#if defined(__x86_64__) || defined(__i386__)
#include "sim/wide_sse2.h"
#elif defined(__aarch64__)
#include "sim/wide_neon.h"
#else
#error "pond's wide-float tables cover x86 (SSE2 and up) and aarch64 (NEON)"
#endif

namespace pond::sim {
inline namespace POND_ISA {
#if defined(__aarch64__)
using WideBaseline = WideNeon;
#else
using WideBaseline = WideSse2;
#endif
}  // namespace POND_ISA
}  // namespace pond::sim
