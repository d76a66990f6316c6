#!/usr/bin/env bash
# What a rendered frame costs `pond render` with every picture effect on and with every one off:
# the wall time of `--frames 70` minus that of `--frames 10` (so start-up, the first steps and the
# PNG cancel), over 60, on SCENE at 1280x720 (the release build), the four runs of a round
# alternated for ROUNDS rounds; medians, and the ratio on / off (issue 26 asks at most 1.5).
#   scripts/render_frames_cost.sh [ROUNDS, default 5] [SCENE, default scenes/demo_257.json]
set -euo pipefail
cd "$(dirname "$0")/.."
rounds=${1:-5}
scene=${2:-scenes/demo_257.json}
pond=build/src/app/pond
[ -x "$pond" ] || { echo "render_frames_cost.sh: build first ($pond is missing)" >&2; exit 2; }
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 - "$scene" "$work/off.json" << 'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
scene.setdefault("view", {}).update(reflections=False, caustics=False, shadows=False)
json.dump(scene, open(sys.argv[2], "w"))
PY
seconds() {  # seconds SCENE FRAMES: the wall time of one run
  local t0 t1
  t0=$(date +%s.%N)
  "$pond" render --scene "$1" --steps 10 --frames "$2" --size 1280x720 --out "$work/out.png" > /dev/null
  t1=$(date +%s.%N)
  awk -v a="$t0" -v b="$t1" 'BEGIN {print b - a}'
}
for ((r = 0; r < rounds; r++)); do
  on=$(awk -v a="$(seconds "$scene" 70)" -v b="$(seconds "$scene" 10)" 'BEGIN {print (a - b) / 60 * 1000}')
  off=$(awk -v a="$(seconds "$work/off.json" 70)" -v b="$(seconds "$work/off.json" 10)" 'BEGIN {print (a - b) / 60 * 1000}')
  echo "$on" >> "$work/on"; echo "$off" >> "$work/off"
  awk -v a="$on" -v b="$off" 'BEGIN {print a / b}' >> "$work/ratio"
  echo "round $((r + 1)): a frame costs $on ms with every effect, $off ms with none" >&2
done
median() { sort -n "$1" | awk '{a[NR] = $1} END {print NR % 2 ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
echo "pond render $scene 1280x720, (--frames 70 minus --frames 10) / 60, $rounds rounds (medians):"
echo "  every effect on  $(median "$work/on") ms a frame"
echo "  every effect off $(median "$work/off") ms a frame"
echo "  ratio on / off   $(median "$work/ratio") (paired by round)"
