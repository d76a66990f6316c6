#!/bin/sh
# The demo's checkpoints, by script under a virtual X server (docs/checkpoints.md): a splash, then
# `save` at frame 4 and again at frame 24 with nothing between; `load` of the first at frame 25 and
# `save` right after. pond simulate --resume of the first for the steps between the two saves gives
# the second's state (the demo steps as simulate does); the save after the load is the first's state
# at the first's step; a save to a missing folder is said in the panel's line and the demo goes on.
#   demo_checkpoint_test.sh POND WORK
set -u
pond=$1 work=$2
rm -rf "$work" && mkdir -p "$work" "$XDG_RUNTIME_DIR" && chmod 700 "$XDG_RUNTIME_DIR" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
cat > "$work/run.script" <<SCRIPT
frame 1 click 240 160
frame 2 drop 300 150
frame 4 save $work/a.ckpt
frame 24 save $work/b.ckpt
frame 25 load $work/a.ckpt
frame 25 save $work/c.ckpt
frame 26 key F9
SCRIPT
timeout 300 xvfb-run -a -s "-screen 0 800x600x24" "$pond" demo --frames 30 --size 480x300 --no-vsync --validation \
  --script "$work/run.script" > "$work/demo.out" 2> "$work/demo.err" || fail "demo: exit $?: $(tail -n 3 "$work/demo.err")"
for f in a b c; do [ -f "$work/$f.ckpt" ] || fail "no $f.ckpt: $(cat "$work/demo.out")"; done
grep -q "not loaded: 'pond.ckpt' does not exist\|not loaded: file 'pond.ckpt' does not exist" "$work/demo.out" ||
  fail "F9 without a file: not said: $(grep F9 "$work/demo.out")"

at() { "$pond" simulate --resume "$1" --steps "$2" --out "$work/x.npy" > "$work/at.out" 2>&1 || fail "resume $1: $(cat "$work/at.out")"; }
hash_of() { sed -n 's/^state hash //p' "$work/at.out"; }
step_of() { sed -n 's/^resumed at step \([0-9]*\) .*/\1/p' "$work/at.out"; }
at "$work/a.ckpt" 0; sa=$(step_of); ha=$(hash_of)
at "$work/b.ckpt" 0; sb=$(step_of); hb=$(hash_of)
at "$work/c.ckpt" 0; sc=$(step_of); hc=$(hash_of)
[ -n "$sa" ] && [ -n "$sb" ] && [ "$sb" -gt "$sa" ] || fail "the saves' steps: a $sa, b $sb"
at "$work/a.ckpt" $((sb - sa))
[ "$(hash_of)" = "$hb" ] || fail "a + $((sb - sa)) steps resumed: $(hash_of), the demo's b: $hb"
[ "$sc" = "$sa" ] && [ "$hc" = "$ha" ] || fail "saved after loading a: step $sc hash $hc, a: step $sa hash $ha"

if [ $failures -eq 0 ]; then echo "the demo's checkpoints resume as the demo runs"; exit 0; fi
exit 1
