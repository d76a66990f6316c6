#!/usr/bin/env bash
# Sets up, builds and runs every test: the release build (CPU, GPU on lavapipe with the validation
# layer, the IA-32 golden hash, CLI, faults); the sanitize build (clang: ASan + UBSan and libFuzzer
# coverage) with the CPU tests and each libFuzzer target for a short time on its committed corpus
# (FUZZ_SECONDS, default 10 here; scripts/fuzz.sh); the GPU solver's tests (context, float policy,
# SPIR-V checks, a tenth of the parity suite's steps) under ASan + UBSan too; the GPU tests under
# the discrete-GPU test layer (both denormal settings); the aarch64 build's tests under qemu-aarch64;
# the aarch64 Vulkan build's `pond check` and `pond render` on Debian's arm64 lavapipe under
# qemu-aarch64; then the release tests.
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
# The host's layer (arm64's is installed too, for the arm64 Vulkan stage).
validation_json=$(dpkg -L "vulkan-validationlayers:$(dpkg --print-architecture)" | grep -m1 'VkLayer_khronos_validation.json$')
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

# The aarch64 build with Vulkan (the arm64-gpu preset: pond only) on Debian's arm64 lavapipe under
# qemu-aarch64, with the arm64 validation layer: `pond check`'s cases, shortened, bit-identical to
# the CPU; one small `pond render --validation`, the pond right side up (png_probe from the release
# build). The submerged effect is off: arm64 llvmpipe aborts compiling its shader (docs/water.md).
stage "arm64 Vulkan build, pond check and render under qemu-aarch64"
cmake --preset arm64-gpu
cmake --build --preset arm64-gpu -j "$jobs"
arm_gpu=$PWD/build-arm64-gpu/ci
mkdir -p "$arm_gpu"
arm_pond() { MESA_SHADER_CACHE_DIR="$arm_gpu/mesa-shader-cache" qemu-aarch64 build-arm64-gpu/src/app/pond "$@"; }
arm_fail() { echo "scripts/test.sh: arm64 Vulkan: $1" >&2; exit 1; }
# `pond check` has no --validation: the layer goes in by the loader, set as --validation sets it
# (warnings and errors, synchronization validation), and prints its messages to stdout.
printf 'khronos_validation.report_flags = error,warn\n' > "$arm_gpu/vk_layer_settings.txt"
VK_INSTANCE_LAYERS=VK_LAYER_KHRONOS_validation VK_LAYER_SETTINGS_PATH="$arm_gpu/vk_layer_settings.txt" \
  VK_LAYER_ENABLES=VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT \
  arm_pond check --steps 200 2>&1 | tee "$arm_gpu/check.out" || arm_fail "pond check: exit $?"
grep -Eq "^all [0-9]+ cases bit-identical$" "$arm_gpu/check.out" || arm_fail "pond check: not all cases bit-identical"
if grep -Eqi "validation|VUID" "$arm_gpu/check.out"; then arm_fail "pond check: validation messages"; fi
cat > "$arm_gpu/scene.json" << 'EOF'
{"grid": {"rows": 50, "cols": 50, "spacing": 1.0},
 "physics": {"mass": 4.0, "stiffness": 7.0, "damping": 0.05, "dt": 0.4},
 "border": "fixed", "constraints": [{"kind": "fixed", "rows": [30, 35], "cols": [30, 36]}],
 "perturbations": [{"step": 0, "row": 18, "col": 20, "radius": 2.0, "amplitude": 1.0,
                    "target": "velocity", "mode": "add"}],
 "view": {"submerged": false}}
EOF
rm -f "$arm_gpu/frame.png"
arm_pond render --scene "$arm_gpu/scene.json" --steps 20 --size 64x48 --out "$arm_gpu/frame.png" --validation ||
  arm_fail "pond render: exit $?"
build/tests/demo/png_probe pond "$arm_gpu/frame.png" || arm_fail "pond render: not the pond right side up"

# Last, so its summary closes the output.
stage "release tests"
ctest --preset release -j "$jobs" -LE soak
stage "done"
