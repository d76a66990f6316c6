#!/usr/bin/env bash
# Sets up, builds and runs every test: the release build (CPU, GPU on lavapipe with the validation
# layer, the IA-32 golden hash, CLI, faults); the sanitize build (clang: ASan + UBSan and libFuzzer
# coverage) with the CPU tests and each libFuzzer target for a short time on its committed corpus
# (FUZZ_SECONDS, default 10 here; scripts/fuzz.sh); the GPU solver's tests (context, float policy,
# SPIR-V checks, a tenth of the parity suite's steps) under ASan + UBSan too; the GPU tests under
# the discrete-GPU test layer (both denormal settings); the aarch64 build's tests under qemu-aarch64;
# then the release tests.
# The soak (label soak, ~12 min) is left out: scripts/soak.sh runs it. Exits non-zero on the first
# failure.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
jobs=$(nproc)
stage() { echo "== scripts/test.sh: $1 ($SECONDS s)"; }
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}

stage "release build"
cmake --preset release -DPOND_REQUIRE_IA32=ON -DPOND_TEST_DEVICE="${POND_DEVICE:-llvmpipe}"
cmake --build --preset release -j "$jobs"

stage "ASan + UBSan build (CPU tests, fuzzers) and CPU tests"
cmake --preset sanitize
cmake --build --preset sanitize -j "$jobs"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --preset sanitize -j "$jobs"

stage "fuzzing"
FUZZ_SECONDS=${FUZZ_SECONDS:-10} FUZZ_JOBS=$jobs scripts/fuzz.sh

# The GPU solver's tests under ASan + UBSan too (lavapipe itself is not instrumented; leak checks
# off, since the driver is unloaded before LeakSanitizer could name its allocations).
stage "ASan + UBSan build and GPU solver tests"
# Only the two test programs it runs (label gpu_solver): not the renderer, the app or the rest again.
cmake --preset sanitize-gpu -DPOND_TEST_DEVICE="${POND_DEVICE:-llvmpipe}"
cmake --build --preset sanitize-gpu -j "$jobs" --target gpu_tests gpu_parity_tests
ctest --preset sanitize-gpu -j "$jobs"

# The GPU suite again under the discrete-GPU test layer (layers/, built by the release preset):
# staging, flush/invalidate of non-coherent memory, no shaderInt64, with and without
# shaderDenormPreserveFloat32, the validation layer above it (docs/layer.md). The whole
# GPU label with the feature, then without it only the solver's tests and `pond check` (denormals
# reach only the solver).
# The parity runs at 0.3 of their length here; the plain run below keeps the full length. The
# installed and packaged pond's tests (label install) run their own layer; the plain run has them.
stage "GPU tests under the discrete-GPU layer"
validation_json=$(dpkg -L vulkan-validationlayers | grep -m1 'VkLayer_khronos_validation.json$')
for pass in "1 gpu" "0 gpu_solver|parity"; do
  read -r denorm label <<< "$pass"
  VK_LAYER_PATH="$(dirname "$validation_json"):$PWD/build/layers" \
  VK_INSTANCE_LAYERS=VK_LAYER_KHRONOS_validation:VK_LAYER_POND_discrete_gpu \
  POND_DISCRETE_GPU_DENORM_PRESERVE=$denorm POND_PARITY_STEP_SCALE=0.3 \
    ctest --preset release -j "$jobs" -L "$label" -LE "soak|layer|install"
done

# The aarch64 cross build (the arm64 preset: clang-14 over Debian's cross sysroot, CPU only) and its Vulkan-free
# tests under qemu-aarch64: the unit, CLI and fuzz-replay tests, the parity scenes' hashes of its
# scalar and neon solvers against the release build's x86-64 scalar ones (tests/sim/
# cross_parity_test.sh), no fused multiply-add in its pond, and its .deb (docs/water.md).
stage "arm64 build and tests under qemu-aarch64"
cmake --preset arm64 -DPOND_HOST_PARITY_HASHES="$PWD/build/tests/sim/parity_hashes"
cmake --build --preset arm64 -j "$jobs"
ctest --preset arm64 -j "$jobs"

# Last, so its summary closes the output.
stage "release tests"
ctest --preset release -j "$jobs" -LE soak
stage "done"
