#!/bin/sh
# The demo when its device fails, under the discrete-GPU layer's faults (docs/layer.md#faults) and a
# virtual X server: a scripted run (a splash, a drag of the camera) with the device lost at a
# quarter, a half and three quarters of its submissions, and memory short at an allocation in the
# middle. Each run exits 0, says that it made the device again and that the device is back, logs no
# validation message, and its last frame is the run without faults' but for the panel's figures
# (the water went on with the same bits; png_probe share).
#   demo_device_lost_test.sh POND PNG_PROBE WORK   (the layers' environment comes from CTest)
set -u
pond=$1 probe=$2 work=$3
rm -rf "$work" && mkdir -p "$work" "$XDG_RUNTIME_DIR" && chmod 700 "$XDG_RUNTIME_DIR" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
printf 'frame 2 click 240 180\nframe 6 drag left 240 150 300 150\nframe 14 click 200 200 shift\n' > "$work/run.script"
# The default scene, and the same with the effects off: the picture a run short of memory goes on with.
scene='"grid": {"rows": 50, "cols": 50}, "constraints": [{"kind": "fixed", "rows": [30, 35], "cols": [30, 36]}],
  "perturbations": [{"row": 18, "col": 20, "radius": 2.0, "amplitude": 1.0}]'
echo "{$scene}" > "$work/pond.json"
echo "{$scene, \"view\": {\"reflections\": false, \"caustics\": false, \"shadows\": false, \"submerged\": false}}" > "$work/plain.json"

demo() {  # demo NAME [FAULT [SCENE]]: one scripted run of 30 frames, exit code in $code
  POND_DISCRETE_GPU_FAULT=${2:-} POND_DISCRETE_GPU_STATS=$work/$1.stats \
    timeout 300 xvfb-run -a -s "-screen 0 800x600x24" "$pond" demo --scene "$work/${3:-pond}.json" --frames 30 --size 480x300 --no-vsync \
    --script "$work/run.script" --screenshot "$work/$1.png" > "$work/$1.out" 2> "$work/$1.err"
  code=$?
}

for name in plain pond; do
  demo $name "" $name
  [ $code -eq 0 ] || { echo "FAIL: the run without faults ($name.json): exit $code: $(cat "$work/$name.err")"; exit 1; }
done
submits=$(sed -n 's/.*"submits": \([0-9]*\).*/\1/p' "$work/pond.stats")
allocations=$(sed -n 's/.*"allocations": \([0-9]*\).*/\1/p' "$work/pond.stats")
echo "a run without faults: $submits submits, $allocations allocations"

check() {  # check NAME WHAT LIKE: LIKE is the run without faults it must look like
  [ $code -eq 0 ] || { fail "$2: exit $code: $(tail -n 3 "$work/$1.err")"; return; }
  [ "$(grep -c "fault injected" "$work/$1.err")" = 1 ] || fail "$2: not one fault: $(grep "fault injected" "$work/$1.err")"
  grep -q "making the device again" "$work/$1.out" || fail "$2: the demo does not say it makes the device again"
  grep -q "is back" "$work/$1.out" || fail "$2: the demo does not say the device is back"
  if grep -q "VUID\|Validation Error\|Validation Warning" "$work/$1.err" "$work/$1.out"; then
    fail "$2: a validation message: $(grep -m1 "VUID\|Validation" "$work/$1.err" "$work/$1.out")"
  fi
  share=$("$probe" share "$work/$3.png" "$work/$1.png" 8) || fail "$2: no last frame to compare"
  awk -v s="$share" 'BEGIN { exit !(s < 0.01) }' ||
    fail "$2: the last frame differs from the run without faults in $share of its pixels"
}
for n in $((submits / 4)) $((submits / 2)) $((3 * submits / 4)); do
  demo "lost$n" "device-lost@submit:$n"
  check "lost$n" "device lost at submit $n of $submits" pond
done
n=$((allocations / 2))
demo "oodm$n" "out-of-device-memory@allocate:$n"
check "oodm$n" "out of device memory at allocation $n of $allocations" plain
grep -q "effects off" "$work/oodm$n.out" || fail "memory short: the demo does not say it turned the effects off"

if [ $failures -eq 0 ]; then echo "the demo survived every fault tried"; exit 0; fi
echo "$failures demo fault case(s) failed"
exit 1
