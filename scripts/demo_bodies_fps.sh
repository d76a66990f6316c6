#!/usr/bin/env bash
# What the bodies cost the demo: `pond demo --frames 200 --size 1280x720 --no-vsync` on
# scenes/demo_257.json and on scenes/demo_257_bodies.json (the same pond with 8 bodies: a sphere
# pulled across, seven floating balls), alternated for ROUNDS rounds under one tuned virtual X
# server (scripts/demo_timing.sh), and the median ms per frame of each.
#   scripts/demo_bodies_fps.sh [ROUNDS, default 5]       (after a release build: build/src/app/pond)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/demo_timing.sh
demo_timing_init demo_bodies_fps.sh "${1:-5}"
start_x "MALLOC_TOP_PAD_=67108864"
for ((r = 0; r < rounds; r++)); do
  for scene in demo_257 demo_257_bodies; do
    ms=$(demo_ms "$display" "scenes/$scene.json")
    echo "$ms" >> "$work/$scene"
    echo "round $((r + 1)): $scene: $ms ms/frame" >&2
  done
done
echo "pond demo, 257^2, 1280x720, no vsync, $rounds rounds (median, min-max ms per frame):"
for scene in demo_257 demo_257_bodies; do print_median "$scene" "$work/$scene"; done
