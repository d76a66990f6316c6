#!/bin/sh
# `pond bench` on a device without timestamps (VK_LAYER_POND_discrete_gpu with
# POND_DISCRETE_GPU_NO_TIMESTAMPS=1: timestampComputeAndGraphics false, timestampValidBits 0): it
# says so, still draws and times the frames, and writes no per-pass GPU times; validation on.
#   bench_no_timestamps_test.sh POND WORK_DIR      (the layer's environment comes from CTest)
set -u
pond=$1 work=$2
mkdir -p "$work" "$XDG_RUNTIME_DIR" && chmod 700 "$XDG_RUNTIME_DIR" && rm -f "$work"/*
export POND_DISCRETE_GPU_NO_TIMESTAMPS=1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
"$pond" bench --quick --only frame --validation --json "$work/run.json" > "$work/out" 2> "$work/err"
rc=$?
cat "$work/out"
[ $rc -eq 0 ] || fail "exit $rc: $(cat "$work/err")"
grep -q "no timestamps: timestampComputeAndGraphics is false, timestampValidBits is 0 on its queue" "$work/out" || fail "the device line does not say it has no timestamps"
grep -q "^note: no per-pass GPU times: the device has no timestamps" "$work/out" || fail "no note on the missing pass times"
python3 - "$work/run.json" <<'PY' || fail "the JSON"
import json, sys
r = json.load(open(sys.argv[1]))
names = [f["name"] for f in r["figures"]]
ok = (r["device"]["timestamps"] is False and r["device"]["type"] == "discrete GPU"
      and "frame.all_effects" in names and "frame.no_effects" in names
      and not any(n.startswith("frame.gpu.") for n in names))
print(names, r["device"])
sys.exit(0 if ok else 1)
PY
[ $failures -eq 0 ] && echo "bench without timestamps: all checks passed"
exit $failures
