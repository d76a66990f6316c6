#!/usr/bin/env bash
# The demo's frame rate as the README reports it: `pond demo --frames 200 --size 1280x720
# --no-vsync` on scenes/demo_129.json and scenes/demo_257.json, under two virtual X servers at
# once, each scene and server in turn for ROUNDS rounds (so a busy machine slows them alike), and
# the median ms per frame of each.
#
# The two servers differ only in the X server's own malloc: Xvfb reads each frame's XPutImage
# request (lavapipe's software present sends the whole 3.7 MB image through the socket: its WSI has
# no shared-memory path without DRI3) into a buffer it frees afterwards, and glibc hands that memory
# back to the kernel and faults it in again every frame, ~19 ms a frame on this
# machine. MALLOC_TOP_PAD_ keeps it mapped; pond itself is unchanged.
#   scripts/demo_fps.sh [ROUNDS, default 5]       (after a release build: build/src/app/pond)
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-5}
[[ $rounds =~ ^[1-9][0-9]*$ ]] || { echo "demo_fps.sh: ROUNDS must be a positive integer, not '$rounds'" >&2; exit 2; }
pond=build/src/app/pond
[ -x "$pond" ] || { echo "demo_fps.sh: $pond is missing: build first (cmake --preset release && cmake --build --preset release)" >&2; exit 2; }
command -v Xvfb > /dev/null || { echo "demo_fps.sh: Xvfb is missing: scripts/setup.sh installs it" >&2; exit 2; }
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
work=$(mktemp -d)
pids=()
cleanup() { kill "${pids[@]}" 2> /dev/null || true; rm -rf "$work"; }
trap cleanup EXIT

# Starts an Xvfb (extra environment in $1) and prints its display number.
start_x() {
  env $1 Xvfb -displayfd 3 -screen 0 1600x1000x24 -nolisten tcp 3> "$work/fd.$2" > /dev/null 2>&1 &
  pids+=($!)
  for _ in $(seq 50); do [ -s "$work/fd.$2" ] && break; sleep 0.1; done
  [ -s "$work/fd.$2" ] || { echo "demo_fps.sh: Xvfb did not start" >&2; exit 1; }
  cat "$work/fd.$2"
}
plain=$(start_x "" plain)
tuned=$(start_x "MALLOC_TOP_PAD_=67108864" tuned)

configs=("129 $plain default" "129 $tuned tuned" "257 $plain default" "257 $tuned tuned")
for ((r = 0; r < rounds; r++)); do
  for c in "${configs[@]}"; do
    read -r n display kind <<< "$c"
    line=$(DISPLAY=:$display "$pond" demo --scene "scenes/demo_$n.json" --frames 200 --size 1280x720 --no-vsync 2>&1 | tail -n 1)
    ms=$(grep -oE '[0-9.]+ ms/frame' <<< "$line" | grep -oE '^[0-9.]+') ||
      { echo "demo_fps.sh: the demo failed: $line" >&2; exit 1; }
    echo "$ms" >> "$work/$n.$kind"
    echo "round $((r + 1)): ${n}^2, $kind Xvfb: $ms ms/frame" >&2
  done
done
echo "pond demo, 1280x720, no vsync, $rounds rounds (median, min-max ms per frame):"
for c in "${configs[@]}"; do
  read -r n _ kind <<< "$c"
  sort -n "$work/$n.$kind" | awk -v label="${n}^2, $kind Xvfb" '{a[NR] = $1}
    END {m = NR % 2 ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2;
         printf "  %-22s %6.2f ms (%5.1f FPS)  %.2f-%.2f\n", label, m, 1000 / m, a[1], a[NR]}'
done
