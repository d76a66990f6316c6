#pragma once
// The SIMD features the CPU code chooses between at run time, as this CPU has them: x86's SSE2,
// AVX2 and AVX-512F, aarch64's NEON (Advanced SIMD). A feature of the other architecture is never
// present. Tests hide features with POND_CPU_FEATURES_MASK=avx2 (sse2|avx2|avx512f|neon,
// comma-separated): a masked x86 feature and every wider one then count as missing (no x86 CPU
// has AVX-512F without AVX2); neon hides only itself.

namespace pond::core {

enum class CpuFeature { sse2, avx2, avx512f, neon };  // x86's narrowest first, then aarch64's

// Whether POND_CPU_FEATURES_MASK hides `f`. Read on every call, so a test can set it; an unknown
// name in it throws InputError rather than hiding nothing.
bool cpu_feature_masked(CpuFeature f);
// This CPU has `f` and the mask does not hide it.
bool cpu_has(CpuFeature f);
// Throws InputError if the mask names an unknown feature: for a command to report it as itself,
// before a part that reads it mid-way (the LOD builder, once a frame) blames its own input.
void validate_cpu_features_mask();

}  // namespace pond::core
