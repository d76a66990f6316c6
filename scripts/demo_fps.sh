#!/usr/bin/env bash
# The demo's frame rate as docs/demo.md reports it: `pond demo --frames 200 --size 1280x720
# --no-vsync` on scenes/demo_129.json and scenes/demo_257.json, under two virtual X servers at
# once (stock, and "tuned" with MALLOC_TOP_PAD_: scripts/demo_timing.sh says why), each scene and
# server in turn for ROUNDS rounds (so a busy machine slows them alike), and the median ms per
# frame of each; then the median CPU time a frame (every thread, lavapipe's rendering included: over
# the machine's cores, the least a frame can take however it overlaps; docs/demo.md).
#   scripts/demo_fps.sh [ROUNDS, default 5]       (after a release build: build/src/app/pond)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/demo_timing.sh
demo_timing_init demo_fps.sh "${1:-5}"
start_x ""
plain=$display
start_x "MALLOC_TOP_PAD_=67108864"
tuned=$display

configs=("129 $plain default" "129 $tuned tuned" "257 $plain default" "257 $tuned tuned")
for ((r = 0; r < rounds; r++)); do
  for c in "${configs[@]}"; do
    read -r n display kind <<< "$c"
    ms=$(demo_ms "$display" "scenes/demo_$n.json" "$work/$n.$kind.cpu")
    echo "$ms" >> "$work/$n.$kind"
    echo "round $((r + 1)): ${n}^2, $kind Xvfb: $ms ms/frame" >&2
  done
done
echo "pond demo, 1280x720, no vsync, $rounds rounds (median, min-max ms per frame):"
for c in "${configs[@]}"; do
  read -r n _ kind <<< "$c"
  print_median "${n}^2, $kind Xvfb" "$work/$n.$kind"
done
echo "CPU time a frame, every thread of pond's (median, min-max ms; $(nproc) cores give $(nproc) x the frame's ms):"
for c in "${configs[@]}"; do
  read -r n _ kind <<< "$c"
  print_median "${n}^2, $kind Xvfb" "$work/$n.$kind.cpu" no-fps
done
