#!/usr/bin/env bash
# Builds the libFuzzer targets in the sanitize preset's tree (build-sanitize: clang, coverage,
# ASan + UBSan, CPU-only: the targets never reach Vulkan) and runs each on its committed seed corpus
# for a bounded time.
#
#   scripts/fuzz.sh [TARGET...]      TARGET: scene npy cli checkpoint (default: all four)
#   FUZZ_SECONDS=60                  time per target (default 60)
#   FUZZ_JOBS=$(nproc)               build jobs
#
# The committed corpus (tests/fuzz/corpus/<target>/) is read, never written: new inputs go to a
# scratch corpus in the build folder. A crash, leak, UB report or timeout stops the run, leaves the
# input as <build>/fuzz-artifacts/<target>/crash-* (or timeout-*, leak-*) and exits non-zero. To keep
# it fixed: copy it to tests/fuzz/regressions/<target>/<what-it-broke>, fix the bug, and
# fuzz_replay_tests replays it in every build from then on.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${FUZZ_SECONDS:-60}
build=build-sanitize
jobs=${FUZZ_JOBS:-$(nproc)}
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(scene npy cli checkpoint)

cmake --preset sanitize > /dev/null
cmake --build --preset sanitize -j "$jobs" --target "${targets[@]/#/fuzz_}"

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
status=0
for t in "${targets[@]}"; do
  scratch="$build/fuzz-corpus/$t" artifacts="$build/fuzz-artifacts/$t"
  mkdir -p "$scratch" "$artifacts"
  dict=()
  [ -f "tests/fuzz/$t.dict" ] && dict=(-dict="tests/fuzz/$t.dict")
  echo "fuzz: $t for ${seconds}s" >&2
  # -timeout: one input taking over 10 s is a hang; -rss_limit_mb: a runaway allocation is a bug.
  if ! "$build/tests/fuzz/fuzz_$t" "$scratch" "tests/fuzz/corpus/$t" "${dict[@]}" \
        -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 \
        -artifact_prefix="$artifacts/" -print_final_stats=1 2> "$build/fuzz-$t.log"; then
    status=1
    echo "fuzz: $t FAILED; the input is in $artifacts/, the report:" >&2
    grep -v '^#' "$build/fuzz-$t.log" | tail -n 60 >&2
  else
    grep -E '^stat::number_of_executed_units|^stat::peak_rss_mb' "$build/fuzz-$t.log" |
      sed "s/^/fuzz: $t /" >&2
    tail -n 1 "$build/fuzz-$t.log" >&2
  fi
done
exit $status
