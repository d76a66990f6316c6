#!/bin/sh
# The bodies in the water in the windowed demo (issue 16), as a person uses them, under a virtual X
# server with the validation layer on (any message fails the run):
#  - a left press on the kinematic sphere grabs it, moves over ten frames drag it, the release lets
#    it go further along: the demo says so, and the screenshot shows the sphere gone from where it
#    was and arrived where it was dragged;
#  - `drop` (the O key at the cursor) drops a floating ball on the water, which shows there;
#  - `remove-body` removes the scene's floating ball (gone from the picture) and `add-ball` adds one
#    (there in the middle of the pond);
#  - a left drag that starts off every body still orbits the camera (and grabs nothing);
#  - bad press, drop, release, remove-body and add-ball lines exit 2 naming the line.
# Each screenshot is compared with the same run without those events (png_probe: the share of
# pixels around a point that differ by more than 40 levels).
# Usage: bodies_test.sh PATH/TO/pond PATH/TO/png_probe TESTS/demo WORKDIR
set -u
pond=$1
probe=$2
src=$3
work=$4
rm -rf "$work" && mkdir -p "$work" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# Pixels of tests/demo/bodies_scene.json at 640x400 (its camera; found with `pond render --scene
# tests/demo/bodies_scene.json --steps 0 --size 640x400`): the sphere at world (14, 0.5, 24), where
# it is dragged to (18, 0.5, 36), the floating ball at (50, 2, 16), the drop point (32, 0, 34), the
# middle of the pond where add-ball drops its ball (32, 1, 24; projected by the scene's camera).
SPHERE_X=187; SPHERE_Y=184
DRAGGED_X=205; DRAGGED_Y=263
BALL_X=444; BALL_Y=137
DROP_X=320; DROP_Y=253
MIDDLE_X=320; MIDDLE_Y=186

# The new script events refuse bad words like the others: exit 2 before any window, naming the line.
for bad in 'frame 1 remove-body x' 'frame 1 press left 10' 'frame 1 drop 5' 'frame 1 release sideways 1 2' \
           'frame 1 add-ball now'; do
  printf 'frame 0 key F2\n%s\n' "$bad" > "$work/bad.script"
  env -u DISPLAY "$pond" demo --frames 3 --script "$work/bad.script" > /dev/null 2> "$work/bad.stderr"
  rc=$?
  [ $rc -eq 2 ] && grep -q "line 2" "$work/bad.stderr" || fail "'$bad': exit $rc, $(cat "$work/bad.stderr")"
done

cat > "$work/bodies.script" <<SCRIPT
frame 0 key F2
frame 4 press left $SPHERE_X $SPHERE_Y
SCRIPT
# Ten moves of a tenth of the way each, one a frame.
i=1
while [ $i -le 10 ]; do
  echo "frame $((4 + i)) move $((SPHERE_X + (DRAGGED_X - SPHERE_X) * i / 10)) $((SPHERE_Y + (DRAGGED_Y - SPHERE_Y) * i / 10))" \
    >> "$work/bodies.script"
  i=$((i + 1))
done
cat >> "$work/bodies.script" <<SCRIPT
frame 16 release left $DRAGGED_X $DRAGGED_Y
frame 18 drop $DROP_X $DROP_Y
frame 20 remove-body 1
frame 22 add-ball
frame 40 screenshot bodies.png
SCRIPT
printf 'frame 0 key F2\nframe 40 screenshot still.png\n' > "$work/still.script"

for run in bodies still; do
  (cd "$work" && POND_VALIDATION=1 xvfb-run -a -s "-screen 0 1024x768x24" "$pond" demo --scene "$src/bodies_scene.json" \
     --size 640x400 --no-vsync --frames 42 --script "$run.script" > "$run.stdout" 2> "$run.stderr")
  rc=$?
  [ $rc -eq 0 ] || fail "$run run: exit $rc: $(head -c 2000 "$work/$run.stderr")"
  grep -qi "validation\|VUID" "$work/$run.stderr" && fail "$run run: validation messages: $(head -c 2000 "$work/$run.stderr")"
  [ -f "$work/$run.png" ] || fail "$run run: no screenshot"
done
cat "$work/bodies.stdout"

# What the demo says it did.
grep -q "frame 4: holding body 0" "$work/bodies.stdout" || fail "the press on the sphere did not grab it"
released=$(sed -n 's/.*released body 0 at (\([-0-9.]*\), [-0-9.]*, \([-0-9.]*\)).*/\1 \2/p' "$work/bodies.stdout")
[ -n "$released" ] || fail "the release did not let body 0 go"
echo "${released:-0 0}" | awk '{ exit !($1 > 16 && $1 < 20 && $2 > 34 && $2 < 38) }' ||
  fail "the sphere was let go at x, z = $released, not near 18, 36 where it was dragged"
grep -q "body 2: a ball dropped" "$work/bodies.stdout" || fail "the drop event dropped no ball"
grep -q "removed body 1" "$work/bodies.stdout" || fail "remove-body 1 removed nothing"

# What the screenshots show, against the run without those events.
# 25 levels: through clear water the sphere's shaded side and the floor shadow it left differ by ~37.
share() { "$probe" "$work/bodies.png" "$work/still.png" "$1" "$2" "$3" 25; }
differs() {  # x y radius what
  s=$(share "$1" "$2" "$3") || { fail "png_probe failed"; return; }
  awk -v s="$s" 'BEGIN { exit !(s > 0.3) }' || fail "$4: only $s of the pixels around ($1, $2) changed"
}
differs "$SPHERE_X" "$SPHERE_Y" 4 "the dragged sphere is still where it was"
differs "$DRAGGED_X" "$DRAGGED_Y" 4 "the dragged sphere did not arrive where it was dragged"
differs "$DROP_X" "$DROP_Y" 3 "no ball where it was dropped"
differs "$BALL_X" "$BALL_Y" 3 "the removed ball is still drawn"
differs "$MIDDLE_X" "$MIDDLE_Y" 3 "add-ball shows no ball in the middle of the pond"
s=$(share 4 4 3)
awk -v s="$s" 'BEGIN { exit !(s == 0) }' || fail "the picture's corner changed ($s): the camera moved"

# Left drag and click off every body: still an orbit and a splash.
printf 'frame 0 key F2\nframe 4 drag left 600 380 500 300\nframe 6 screenshot orbit.png\n' > "$work/orbit.script"
printf 'frame 0 key F2\nframe 6 screenshot still6.png\n' > "$work/still6.script"
for run in orbit still6; do
  (cd "$work" && xvfb-run -a -s "-screen 0 1024x768x24" "$pond" demo --scene "$src/bodies_scene.json" \
     --size 640x400 --no-vsync --frames 8 --script "$run.script" > "$run.stdout" 2> "$run.stderr") ||
    fail "$run run: $(head -c 2000 "$work/$run.stderr")"
done
grep -q "holding body" "$work/orbit.stdout" && fail "a drag off every body grabbed one"
# The orbit turns the view: the sphere is no longer where it was on screen.
s=$("$probe" "$work/orbit.png" "$work/still6.png" "$SPHERE_X" "$SPHERE_Y" 4 40)
awk -v s="$s" 'BEGIN { exit !(s > 0.3) }' || fail "a left drag off the bodies did not orbit the camera ($s changed)"

# O on a calm pond (issue 25): the ball splashes, bobs and settles at its waterline, floating: it
# is drawn where it was dropped, and the water around it (from 2.7 radii out) looks as calm as
# without it: no pit, no rings left.
printf 'frame 0 key F2\nframe 2 drop %s %s\nframe 400 screenshot float.png\n' "$DROP_X" "$DROP_Y" > "$work/float.script"
printf 'frame 0 key F2\nframe 400 screenshot calm.png\n' > "$work/calm.script"
for run in float calm; do
  (cd "$work" && POND_VALIDATION=1 xvfb-run -a -s "-screen 0 1024x768x24" "$pond" demo --scene "$src/float_scene.json" \
     --size 640x400 --no-vsync --frames 402 --script "$run.script" > "$run.stdout" 2> "$run.stderr") ||
    fail "$run run: $(head -c 2000 "$work/$run.stderr")"
  grep -qi "validation\|VUID" "$work/$run.stderr" && fail "$run run: validation messages: $(head -c 2000 "$work/$run.stderr")"
done
grep -q "body 0: a ball dropped" "$work/float.stdout" || fail "O dropped no ball on the calm pond"
floated() { "$probe" "$work/float.png" "$work/calm.png" "$1" "$2" "$3" 40; }
s=$(floated "$DROP_X" "$DROP_Y" 3)
awk -v s="$s" 'BEGIN { exit !(s > 0.3) }' || fail "the dropped ball is not where it was dropped ($s changed)"
for dx in -40 40; do
  s=$(floated $((DROP_X + dx)) "$DROP_Y" 6)
  awk -v s="$s" 'BEGIN { exit !(s < 0.05) }' || fail "the water $dx pixels beside the floating ball is not calm ($s changed): a pit or rings"
done

[ $failures -eq 0 ] && echo "demo bodies: all checks passed"
exit $failures
