#!/bin/sh
# The windowed demo as a person and a test use it, on whatever Vulkan device there is (lavapipe in
# CI) under a virtual X server:
#  - 120 frames with scripted splashes, camera gestures, resizes and a toggle of every mode, with
#    the validation layer on (any message fails the run): exit 0, a screenshot mid-run and one of
#    the last frame that show the scene and differ;
#  - the default command and the demo subcommand take the same flags;
#  - without a display: exit 1 and one line saying how to render headless;
#  - a bad script: exit 2 and one line naming the line;
#  - the scene's wind.ripples: a calm pond stays the same picture run to run without them and
#    shows them with them (the demo drives the same session as `pond render`).
# Usage: demo_test.sh PATH/TO/pond SCRIPT WORKDIR
set -u
pond=$1
script=$2
work=$3
rm -rf "$work" && mkdir -p "$work" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
size() { wc -c < "$1" 2> /dev/null || echo 0; }

# No display: exit 1, one line naming the headless command.
env -u DISPLAY -u WAYLAND_DISPLAY "$pond" --frames 3 > "$work/stdout" 2> "$work/stderr"
rc=$?
[ $rc -eq 1 ] || fail "no display: exit $rc, expected 1"
[ "$(wc -l < "$work/stderr")" -eq 1 ] || fail "no display: not one line: $(cat "$work/stderr")"
grep -q "display" "$work/stderr" && grep -q "pond render" "$work/stderr" ||
  fail "no display: the message does not say how to render headless: $(cat "$work/stderr")"

# A bad script: exit 2 before any window, one line naming the file's line.
printf 'frame 1 key H\nframe 2 jump 3\n' > "$work/bad.script"
env -u DISPLAY "$pond" demo --frames 3 --script "$work/bad.script" > "$work/stdout" 2> "$work/stderr"
rc=$?
[ $rc -eq 2 ] || fail "bad script: exit $rc, expected 2"
[ "$(wc -l < "$work/stderr")" -eq 1 ] || fail "bad script: not one line: $(cat "$work/stderr")"
grep -q "line 2" "$work/stderr" || fail "bad script: the line is not named: $(cat "$work/stderr")"
printf 'frame 1 key NOSUCHKEY\n' > "$work/badkey.script"
env -u DISPLAY "$pond" --frames 3 --script "$work/badkey.script" > /dev/null 2> "$work/stderr"
rc=$?
[ $rc -eq 2 ] || fail "bad key name: exit $rc, expected 2 ($(cat "$work/stderr"))"
env -u DISPLAY "$pond" --frames 3 --script "$work/missing.script" > /dev/null 2> "$work/stderr"
rc=$?
[ $rc -eq 2 ] || fail "missing script: exit $rc, expected 2 ($(cat "$work/stderr"))"

# The scripted run, validation on. Run in the work dir: F12 writes pond-0000.png there, and the
# script's `screenshot mid.png` too.
cp "$script" "$work/every_mode.script"
(cd "$work" && POND_VALIDATION=1 xvfb-run -a -s "-screen 0 1600x1000x24" "$pond" demo --frames 120 \
   --script every_mode.script --screenshot final.png > stdout 2> stderr)
rc=$?
[ $rc -eq 0 ] || fail "scripted run: exit $rc: $(head -c 2000 "$work/stderr")"
grep -qi "validation\|VUID" "$work/stderr" && fail "validation messages: $(head -c 2000 "$work/stderr")"
grep -q "120 frames" "$work/stdout" || fail "no summary line: $(cat "$work/stdout")"
for shot in mid.png final.png pond-0000.png; do
  [ -f "$work/$shot" ] || { fail "no $shot"; continue; }
  head -c 8 "$work/$shot" | od -An -c | grep -q "P   N   G" || fail "$shot is not a PNG"
  # A flat or empty picture compresses to a few kB; the pond, its shore and the panel do not.
  [ "$(size "$work/$shot")" -gt 30000 ] || fail "$shot is too small to show the scene ($(size "$work/$shot") bytes)"
done
cmp -s "$work/mid.png" "$work/final.png" && fail "the screenshots at frame 40 and 120 are the same"
[ -z "$(ls "$work" | grep '\.tmp')" ] || fail "temporary file left behind"

# The same flags on the default command: a short run with a screenshot.
(cd "$work" && xvfb-run -a "$pond" --frames 4 --quiet --screenshot short.png > short.stdout 2> short.stderr)
rc=$?
[ $rc -eq 0 ] || fail "pond --frames 4: exit $rc: $(cat "$work/short.stderr")"
[ -f "$work/short.png" ] || fail "pond --frames 4 --screenshot: no picture"
[ -s "$work/short.stdout" ] && fail "--quiet still printed: $(cat "$work/short.stdout")"

# wind.ripples: the same calm pond (no splash, no tree, the panel hidden) with and without them.
calm='{"grid": {"rows": 40, "cols": 40}, "wind": {"strength": 9, "ripples": RIPPLES}}'
echo "$calm" | sed 's/RIPPLES/false/' > "$work/calm.json"
echo "$calm" | sed 's/RIPPLES/true/' > "$work/rippled.json"
printf 'frame 0 key F2\n' > "$work/no_panel.script"
for run in calm calm2 rippled; do
  scene=$work/${run%2}.json
  (cd "$work" && xvfb-run -a "$pond" --frames 30 --quiet --script no_panel.script --scene "$scene" \
     --screenshot "$run.png" > "$run.stdout" 2> "$run.stderr") || fail "$run run: $(cat "$work/$run.stderr")"
done
cmp -s "$work/calm.png" "$work/calm2.png" || fail "a calm pond without ripples drew two different pictures"
cmp -s "$work/calm.png" "$work/rippled.png" && fail "wind.ripples: the demo drew no ripples"

[ $failures -eq 0 ] && echo "demo: all checks passed"
exit $failures
