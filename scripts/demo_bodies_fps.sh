#!/usr/bin/env bash
# What the bodies cost the demo: `pond demo --frames 200 --size 1280x720 --no-vsync` on
# scenes/demo_257.json and on scenes/demo_257_bodies.json (the same pond with 8 bodies: a sphere
# pulled across, seven floating balls), alternated for ROUNDS rounds under one virtual X server
# with MALLOC_TOP_PAD_ (see scripts/demo_fps.sh for why), and the median ms per frame of each.
#   scripts/demo_bodies_fps.sh [ROUNDS, default 5]       (after a release build: build/src/app/pond)
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-5}
[[ $rounds =~ ^[1-9][0-9]*$ ]] || { echo "demo_bodies_fps.sh: ROUNDS must be a positive integer, not '$rounds'" >&2; exit 2; }
pond=build/src/app/pond
[ -x "$pond" ] || { echo "demo_bodies_fps.sh: $pond is missing: build first" >&2; exit 2; }
command -v xvfb-run > /dev/null || { echo "demo_bodies_fps.sh: xvfb-run is missing: scripts/setup.sh installs it" >&2; exit 2; }
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for ((r = 0; r < rounds; r++)); do
  for scene in demo_257 demo_257_bodies; do
    line=$(MALLOC_TOP_PAD_=67108864 xvfb-run -a -s "-screen 0 1600x1000x24" "$pond" demo --scene "scenes/$scene.json" \
             --frames 200 --size 1280x720 --no-vsync 2>&1 | tail -n 1)
    ms=$(grep -oE '[0-9.]+ ms/frame' <<< "$line" | grep -oE '^[0-9.]+') ||
      { echo "demo_bodies_fps.sh: the demo failed: $line" >&2; exit 1; }
    echo "$ms" >> "$work/$scene"
    echo "round $((r + 1)): $scene: $line" >&2
  done
done
echo "pond demo, 257^2, 1280x720, no vsync, $rounds rounds (median, min-max ms per frame):"
for scene in demo_257 demo_257_bodies; do
  sort -n "$work/$scene" | awk -v s="$scene" '{ v[NR] = $1 } END {
    m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
    printf "  %-16s %.2f ms (%.2f-%.2f), %.1f FPS\n", s, m, v[1], v[NR], 1000 / m }'
done
