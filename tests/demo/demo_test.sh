#!/bin/sh
# The windowed demo as a person and a test use it, on whatever Vulkan device there is (lavapipe in
# CI) under a virtual X server:
#  - every key and gesture (every_mode.script on keys_scene.json), with the validation layer on (any
#    message fails the run): each shows what it does in the screenshots (png_probe): a toggle
#    changes the picture and pressing it again restores it bit for bit; the camera gestures move
#    the view and C / Home bring it back; paused, frames repeat; N steps once; R restores the rest
#    picture; steps per frame 0 stands the water still while running; the splash kinds differ; V,
#    B and D change what a replayed splash does, B's fourth press restores it; G switches to the
#    CPU solver (the summary says so) which steps on; F12 saves the next frame; F3 switches the
#    present mode; a resize resizes the screenshots;
#  - the default command and the demo subcommand take the same flags; Esc quits;
#  - without a display: exit 1 and one line saying how to render headless;
#  - a bad script: exit 2 and one line naming the line;
#  - the scene's wind.ripples: a calm pond stays the same picture run to run without them and
#    shows them with them (the demo drives the same session as `pond render`).
# Usage: demo_test.sh PATH/TO/pond PATH/TO/png_probe TESTS/demo WORKDIR
set -u
pond=$1
probe=$2
src=$3
work=$4
rm -rf "$work" && mkdir -p "$work" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

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
# script's screenshots too.
cp "$src/every_mode.script" "$work/every_mode.script"
(cd "$work" && POND_VALIDATION=1 xvfb-run -a -s "-screen 0 1024x768x24" "$pond" demo --frames 148 \
   --scene "$src/keys_scene.json" --size 640x400 --no-vsync --script every_mode.script > stdout 2> stderr)
rc=$?
[ $rc -eq 0 ] || fail "scripted run: exit $rc: $(head -c 2000 "$work/stderr")"
grep -qi "validation\|VUID" "$work/stderr" && fail "validation messages: $(head -c 2000 "$work/stderr")"
grep -q "148 frames" "$work/stdout" || fail "no summary line: $(cat "$work/stdout")"
[ -z "$(ls "$work" | grep '\.tmp')" ] || fail "temporary file left behind"

# share A B LEVELS: the share of pixels of two screenshots more than LEVELS apart.
share() { "$probe" share "$work/$1" "$work/$2" "$3" 2> /dev/null || echo missing; }
same() {  # same A B WHAT: equal bit for bit
  s=$(share "$1" "$2" 0)
  [ "$s" = 0.000000 ] || fail "$3: $1 and $2 differ ($s of the pixels)"
}
differs() {  # differs A B WHAT: over 0.2 % of the pixels more than 8 levels apart
  s=$(share "$1" "$2" 8)
  awk -v s="$s" 'BEGIN { exit !(s > 0.002) }' || fail "$3: $1 and $2 are the same picture ($s differ)"
  echo "  $1 vs $2: $s"
}
differs_near() {  # differs_near A B X Y WHAT: over 5 % of the 41 x 41 pixels around (X, Y) more than 4 levels apart
  s=$("$probe" "$work/$1" "$work/$2" "$3" "$4" 20 4 2> /dev/null || echo missing)
  awk -v s="$s" 'BEGIN { exit !(s > 0.05) }' || fail "$5: $1 and $2 are the same around ($3, $4) ($s differ)"
  echo "  $1 vs $2 around ($3, $4): $s"
}
differs running1.png running2.png "the water does not run"
same paused.png paused2.png "paused, the picture still changes"
differs paused.png help.png "H shows no help"
differs paused.png wire.png "W shows no wireframe"
differs wire.png wire_coarser.png "] does not coarsen the mesh"
same wire.png wire_back.png "[ after ] does not restore the tolerance"
differs wire.png wire_finer.png "[ does not refine the mesh"
differs paused.png no_reflections.png "M does not turn the reflections off"
differs paused.png no_caustics.png "K does not turn the caustics off"
differs paused.png no_shadows.png "L does not turn the shadows off"
differs paused.png no_submerged.png "U does not turn the view under water off"
differs paused.png no_foam.png "F does not turn the foam off"
differs paused.png no_islands.png "I does not take the islands away"
differs paused.png panel.png "F2 shows no panel"
same paused.png toggled_back.png "H/F1, W, ]/[/=, M, K, L, U, F, I and F2 pressed again do not restore the picture"
differs paused.png orbit.png "a left drag does not orbit"
same paused.png home.png "C does not reset the camera"
differs paused.png zoom.png "the wheel does not zoom"
differs zoom.png zoom_pan.png "a middle drag does not pan"
same paused.png home2.png "Home does not reset the camera"
differs paused.png one_step.png "N does not step"
same one_step.png one_step2.png "after N the water does not stay paused"
same rest.png reset.png "R does not bring the water back to rest"
same zero_steps.png zero_steps2.png "with 0 steps a frame the water still moves"
differs running3.png running4.png "with 1 step a frame again the water does not move"
differs reset.png kick.png "a click makes no splash"
differs_near kick.png bump.png 320 230 "a shift-click makes the same splash as a click"
differs bump.png explosion.png "a ctrl-click makes no explosion"
differs explosion.png explosion_vertical.png "V does not make the nodes vertical-only"
differs shore_fixed.png shore_vertical.png "B does not make the shore vertical-only"
differs shore_vertical.png shore_free.png "B a second time does not free the shore"
same shore_fixed.png shore_fixed2.png "B a third time does not fix the shore again"
same reset.png calm.png "a calm pond moved"
differs calm.png rain.png "D brings no rain"
differs before_cpu.png cpu_step.png "after G the water does not step"
same rest.png cpu_reset.png "R on the CPU solver does not bring the water back to rest"
same after_f12.png pond-0000.png "F12 did not save the frame"
[ "$("$probe" size "$work/resized.png")" = "800 500" ] || fail "resized.png is not 800 x 500: $("$probe" size "$work/resized.png")"
grep -q "148 frames at 800x500 on .*, CPU solver ([a-z0-9]*), Fifo:" "$work/stdout" ||
  fail "G or F3 did not switch the solver or the present mode: $(cat "$work/stdout")"
# The summary's CPU time is every thread's: more than none, and no more cores than the machine has.
python3 - "$work/stdout" "$(nproc)" <<'PY' || fail "the summary's CPU time is not a frame's: $(cat "$work/stdout")"
import re, sys
m = re.search(r"; CPU ([0-9.]+) ms a frame \(([0-9.]+) cores busy\)", open(sys.argv[1]).read())
sys.exit(0 if m and float(m.group(1)) > 0 and 0 < float(m.group(2)) <= int(sys.argv[2]) + 0.25 else 1)
PY

# Esc quits: the run ends at the frame it is pressed.
printf 'frame 0 key F2\nframe 3 key ESCAPE\n' > "$work/escape.script"
(cd "$work" && xvfb-run -a "$pond" --frames 50 --size 320x200 --script escape.script > escape.stdout 2> escape.stderr) ||
  fail "Esc: $(cat "$work/escape.stderr")"
grep -q "pond demo: 3 frames" "$work/escape.stdout" || fail "Esc did not end the run: $(cat "$work/escape.stdout")"

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
