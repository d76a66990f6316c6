#!/usr/bin/env bash
# The release build's demo against another pond binary (a baseline build), paired: `pond demo
# --frames 200 --size 1280x720 --no-vsync` on SCENE under one tuned virtual X server
# (scripts/demo_timing.sh), the two binaries alternated for ROUNDS rounds; the median ms a frame of
# each and the median of the paired differences (this build minus the baseline, same round).
#   scripts/demo_vs.sh BASELINE_POND [ROUNDS, default 5] [SCENE, default scenes/demo_257.json]
set -euo pipefail
cd "$(dirname "$0")/.."
baseline=${1:?usage: scripts/demo_vs.sh BASELINE_POND [ROUNDS] [SCENE]}
[ -x "$baseline" ] || { echo "demo_vs.sh: $baseline is not an executable" >&2; exit 2; }
source scripts/demo_timing.sh
demo_timing_init demo_vs.sh "${2:-5}"
scene=${3:-scenes/demo_257.json}
this=$pond
start_x "MALLOC_TOP_PAD_=67108864"
for ((r = 0; r < rounds; r++)); do
  pond=$baseline; b=$(demo_ms "$display" "$scene")
  pond=$this; a=$(demo_ms "$display" "$scene")
  echo "$a" >> "$work/this"; echo "$b" >> "$work/baseline"
  awk -v a="$a" -v b="$b" 'BEGIN {print a - b}' >> "$work/diff"
  echo "round $((r + 1)): this build $a, baseline $b ms/frame" >&2
done
echo "pond demo on $scene, 1280x720, tuned Xvfb, $rounds rounds alternated (median, min-max ms per frame):"
print_median "this build" "$work/this"
print_median "baseline ($baseline)" "$work/baseline"
sort -n "$work/diff" | awk '{a[NR] = $1} END {m = NR % 2 ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2;
  printf "  paired difference (this - baseline): median %+.2f ms, %+.2f to %+.2f\n", m, a[1], a[NR]}'
