#!/usr/bin/env bash
# The soak of issue 8: a 129 x 129 pond with a splash every 50 steps, advanced on the CPU solver and
# on the GPU solver side by side, checked at 100 checkpoints (finite, energy bounded, CPU == GPU bit
# for bit) and for memory growth at the end (the heap in use, and RSS after malloc_trim). Exit 0
# when every check held.
#
#   scripts/soak.sh                       1,000,000 steps (about 12 min on 2 busy cores + lavapipe)
#   scripts/soak.sh --steps 100000        a shorter run; other options: --splash-every K --size N
#                                         --checkpoints C --cpu-only --threads T --device NAME
#   SOAK_BUILD_DIR=build                  the release build folder (configured if missing)
#
# The same run is the CTest test `soak` (label soak, excluded from CI): ctest --preset release -L soak
set -euo pipefail
cd "$(dirname "$0")/.."
build=${SOAK_BUILD_DIR:-build}
if [ ! -f "$build/CMakeCache.txt" ]; then
  if [ "$build" = build ]; then cmake --preset release; else cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release; fi
fi
cmake --build "$build" -j "$(nproc)" --target pond_soak
# Mesa's shader cache and runtime folder stay inside the build tree, as for the GPU tests.
export MESA_SHADER_CACHE_DIR=${MESA_SHADER_CACHE_DIR:-$PWD/$build/tests/gpu/mesa-shader-cache}
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$PWD/$build/tests/gpu/xdg-runtime}
mkdir -p "$MESA_SHADER_CACHE_DIR" "$XDG_RUNTIME_DIR"
args=("$@")
[ ${#args[@]} -gt 0 ] || args=(--steps 1000000)
exec "$build/tests/hardening/pond_soak" "${args[@]}"
