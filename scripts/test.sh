#!/usr/bin/env bash
# Sets up, builds and runs every test: the release build (CPU, GPU on lavapipe with the validation
# layer, the IA-32 golden hash, CLI), then the CPU tests again under AddressSanitizer and
# UndefinedBehaviorSanitizer. Exits non-zero on the first failure.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
jobs=$(nproc)
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}

cmake --preset release -DPOND_REQUIRE_IA32=ON
cmake --build --preset release -j "$jobs"

cmake --preset sanitize
cmake --build --preset sanitize -j "$jobs"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --preset sanitize -j "$jobs"

ctest --preset release -j "$jobs"
