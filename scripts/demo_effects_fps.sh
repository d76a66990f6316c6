#!/usr/bin/env bash
# What each picture effect costs the demo: `pond demo --frames 200 --size 1280x720 --no-vsync` on
# scenes/demo_257.json as it is (every effect on) and with one effect's "view" key set to false, in
# turn for ROUNDS rounds under one tuned virtual X server (scripts/demo_timing.sh); the median ms
# per frame of each, and each effect's cost as the median of its paired differences (the frame
# with everything on minus the frame without it, from the same round).
#   scripts/demo_effects_fps.sh [ROUNDS, default 5] [EFFECT...]   (default: reflections caustics shadows)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/demo_timing.sh
demo_timing_init demo_effects_fps.sh "${1:-5}"
shift $(($# > 0 ? 1 : 0))
effects=("$@")
[ ${#effects[@]} -gt 0 ] || effects=(reflections caustics shadows)
base=scenes/demo_257.json
for e in "${effects[@]}"; do
  [[ $e =~ ^[a-z_]+$ ]] || { echo "demo_effects_fps.sh: '$e' is not an effect name" >&2; exit 2; }
  python3 - "$base" "$e" "$work/no_$e.json" << 'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
scene.setdefault("view", {})[sys.argv[2]] = False
json.dump(scene, open(sys.argv[3], "w"))
PY
done
start_x "MALLOC_TOP_PAD_=67108864"
for ((r = 0; r < rounds; r++)); do
  all=$(demo_ms "$display" "$base")
  echo "$all" >> "$work/all"
  echo "round $((r + 1)): every effect on: $all ms/frame" >&2
  for e in "${effects[@]}"; do
    ms=$(demo_ms "$display" "$work/no_$e.json")
    echo "$ms" >> "$work/without_$e"
    awk -v a="$all" -v b="$ms" 'BEGIN {print a - b}' >> "$work/cost_$e"
    echo "round $((r + 1)): without $e: $ms ms/frame" >&2
  done
done
echo "pond demo, 257^2, 1280x720, no vsync, tuned Xvfb, $rounds rounds (median, min-max ms per frame):"
print_median "every effect on" "$work/all"
for e in "${effects[@]}"; do print_median "without $e" "$work/without_$e"; done
echo "each effect's cost (median of the paired differences, ms per frame):"
for e in "${effects[@]}"; do
  sort -n "$work/cost_$e" | awk -v e="$e" '{a[NR] = $1}
    END {m = NR % 2 ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2; printf "  %-14s %+.2f\n", e, m}'
done
