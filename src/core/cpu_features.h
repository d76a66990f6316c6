#pragma once
// The x86 SIMD features the CPU code chooses between at run time, as this CPU has them.
// Tests hide features with POND_CPU_FEATURES_MASK=avx2 (sse2|avx2|avx512f, comma-separated):
// a masked feature and every wider one then count as missing.

namespace pond::core {

enum class CpuFeature { sse2, avx2, avx512f };  // narrowest first

// Whether POND_CPU_FEATURES_MASK hides `f`. Read on every call, so a test can set it; an unknown
// name in it throws InputError rather than hiding nothing.
bool cpu_feature_masked(CpuFeature f);
// This CPU has `f` and the mask does not hide it.
bool cpu_has(CpuFeature f);
// Throws InputError if the mask names an unknown feature: for a command to report it as itself,
// before a part that reads it mid-way (the LOD builder, once a frame) blames its own input.
void validate_cpu_features_mask();

}  // namespace pond::core
