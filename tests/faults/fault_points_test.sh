#!/bin/sh
# Every fault point of one command under the discrete-GPU test layer (docs/layer.md, faults): a run
# without faults counts the command's submissions and allocations (POND_DISCRETE_GPU_STATS); then
# the device is lost at each submission in turn, and each allocation in turn is out of device
# memory (and the first, middle and last out of host memory). At each, the stated outcome:
#   simulate  exit 0 and the fault-free run's state hash (the CPU goes on from the GPU's last copy)
#   render    exit 0 and the fault-free PNG byte for byte (the CPU solver took over), or exit 1 with
#             one line naming the device and no PNG
#   check     exit 0 and every case identical (an allocation the CPU stood in for), or exit 1 with
#             one line naming the device
# and never a crash, a hang (each run is bounded) or a validation message. The layer sits above the
# validation layer here: a real lost device frees everything in flight, which validation 1.3.239
# would report as objects in use (the layer waits for the real queue and validation sees that).
#   fault_points_test.sh simulate|render|check POND WORK SCENE   (VK_LAYER_PATH etc. from CTest)
set -u
mode=$1 pond=$2 work=$3 scene=$4
rm -rf "$work" && mkdir -p "$work" "$XDG_RUNTIME_DIR" && chmod 700 "$XDG_RUNTIME_DIR" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

args() {  # the command's arguments, writing into $1
  case $mode in
    simulate) echo "simulate --scene $scene --steps 300 --solver gpu --out $1.npy" ;;
    render) echo "render --scene $scene --steps 3 --frames 2 --size 96x64 --out $1.png" ;;
    check) echo "check --steps 3" ;;
  esac
}
attempt() {  # attempt NAME [FAULT]: runs once, exit code in $code, output in NAME.out / NAME.err
  name=$1 fault=${2:-}
  # shellcheck disable=SC2046
  POND_DISCRETE_GPU_FAULT=$fault POND_DISCRETE_GPU_STATS=$work/$name.json \
    timeout 120 "$pond" $(args "$work/$name") > "$work/$name.out" 2> "$work/$name.err"
  code=$?
}

attempt clean
[ $code -eq 0 ] || { echo "FAIL: the run without faults: exit $code: $(cat "$work/clean.err")"; exit 1; }
submits=$(sed -n 's/.*"submits": \([0-9]*\).*/\1/p' "$work/clean.json")
allocations=$(sed -n 's/.*"allocations": \([0-9]*\).*/\1/p' "$work/clean.json")
[ -n "$submits" ] && [ -n "$allocations" ] || { echo "FAIL: no counters: $(cat "$work/clean.json")"; exit 1; }
device=$(grep -o "llvmpipe[^)]*)" "$work/clean.out" | head -n 1)
clean_hash=$(sed -n 's/^state hash //p' "$work/clean.out")

judge() {  # judge NAME WHAT: the outcome of attempt NAME
  name=$1 what=$2
  err=$(grep -v '^VK_LAYER_POND_discrete_gpu: fault injected' "$work/$name.err")
  if grep -q "VUID\|Validation Error\|Validation Warning" "$work/$name.err" "$work/$name.out"; then
    fail "$what: a validation message: $(grep -m1 "VUID\|Validation" "$work/$name.err" "$work/$name.out")"
  fi
  case $mode in
    simulate)
      [ $code -eq 0 ] || { fail "$what: exit $code: $err"; return; }
      [ "$(sed -n 's/^state hash //p' "$work/$name.out")" = "$clean_hash" ] || fail "$what: another state hash"
      if grep -q "fault injected" "$work/$name.err"; then
        grep -q "going on on the CPU" "$work/$name.err" || fail "$what: the switch to the CPU is not said"
      fi ;;
    render|check)
      if [ $code -eq 0 ]; then
        if [ $mode = render ]; then
          cmp -s "$work/$name.png" "$work/clean.png" || fail "$what: exit 0 with another picture"
        else
          grep -q "bit-identical" "$work/$name.out" || fail "$what: exit 0 without every case identical"
        fi
      elif [ $code -eq 1 ]; then
        [ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ] || fail "$what: not one line: $err"
        printf '%s' "$err" | grep -q "was lost\|out of .* memory" || fail "$what: the line does not say what failed: $err"
        [ -z "$device" ] || printf '%s' "$err" | grep -qF "$device" || fail "$what: the line does not name the device: $err"
        [ ! -e "$work/$name.png" ] || fail "$what: exit 1 but a picture was written"
      else
        fail "$what: exit $code: $err"
      fi ;;
  esac
}

# Every fault point must be reached: a run makes the same calls each time.
every_point() {  # every_point NAME FAULT@POINT LAST WHAT: the fault at each point 1 .. LAST
  n=1
  while [ $n -le "$3" ]; do
    attempt "$1$n" "$2:$n"
    judge "$1$n" "$4 $n of $3"
    grep -q "fault injected" "$work/$1$n.err" || fail "$4 $n of $3: the fault never came"
    n=$((n + 1))
  done
}
every_point lost device-lost@submit "$submits" "device lost at submit"
every_point oodm out-of-device-memory@allocate "$allocations" "out of device memory at allocation"
for n in 1 $(( (allocations + 1) / 2 )) "$allocations"; do
  attempt "oohm$n" "out-of-host-memory@allocate:$n"
  judge "oohm$n" "out of host memory at allocation $n of $allocations"
done
# A fault past the last point changes nothing; a malformed one is refused by the layer.
attempt late "device-lost@submit:$((submits + 1000))"
judge late "a fault that never comes"
attempt malformed "device-lost@draw:1"
grep -q "POND_DISCRETE_GPU_FAULT" "$work/malformed.err" || fail "a malformed fault is not reported: $(cat "$work/malformed.err")"

echo "$mode: $submits submits and $allocations allocations tried"
if [ $failures -eq 0 ]; then echo "every fault point of pond $mode held"; exit 0; fi
echo "$failures fault point(s) failed"
exit 1
