#!/bin/sh
# `pond bench` as a user runs it: --quick --json on the test device with validation on, the JSON
# checked against bench/schema.json, every CPU backend's state hash equal per size; --compare
# against a doctored baseline exits 1 naming the doctored figure; bad input exits 2 with one line
# and clobbers nothing.
#   bench_cli_test.sh POND SCHEMA WORK_DIR
set -u
pond=$1 schema=$2 work=$3
here=$(dirname "$0")
mkdir -p "$work" && rm -f "$work"/*
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

"$pond" bench --quick --validation --json "$work/run.json" > "$work/out" 2> "$work/err"
rc=$?
[ $rc -eq 0 ] || fail "bench --quick: exit $rc: $(cat "$work/err")"
cat "$work/out"
python3 "$here/check_schema.py" "$schema" "$work/run.json" || fail "the JSON does not match $schema"
python3 - "$work/run.json" <<'PY' || fail "the figures are not what --quick measures"
import json, sys
r = json.load(open(sys.argv[1]))
names = {f["name"] for f in r["figures"]}
problems = []
for must in ["cpu.scalar.t1.64", "cpu.scalar.t1.128", "gpu.exact.64", "gpu.fast.128", "lod.129", "lod.257",
             "frame.all_effects", "frame.no_effects", "frame.cpu.all_effects", "frame.cpu.no_effects", "frame.gpu.main", "bodies.cpu.8", "bodies.cpu.64",
             "bodies.gpu.8", "bodies.gpu.64"]:
    if must not in names:
        problems.append("no figure " + must)
hashes = {}
for f in r["figures"]:
    if f["name"].startswith("cpu."):
        hashes.setdefault(f["name"].rsplit(".", 1)[1], set()).add(f["hash"])
if not hashes or any(len(h) != 1 for h in hashes.values()):
    problems.append("CPU hashes per size: %s" % hashes)
if not r["hashes_agree"] or not r["device"]["timestamps"]:
    problems.append("hashes_agree %s, timestamps %s" % (r["hashes_agree"], r["device"]["timestamps"]))
for f in r["figures"]:
    if f["name"].startswith("lod.") and f.get("triangles", 0) <= 0:
        problems.append(f["name"] + " has no triangles")
print("\n".join(problems))
sys.exit(1 if problems else 0)
PY

# A baseline whose cpu.scalar.t1.64 was ten times faster: this run is 0.1x of it, past 20 %. Every
# other figure of it is one no run can fall behind (0 node-steps/s, 1e12 ms), so a busy machine's
# noise names no other.
python3 - "$work/run.json" "$work/doctored.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
for f in r["figures"]:
    if f["name"] == "cpu.scalar.t1.64":
        f["median"] *= 10
    else:
        f["median"] = 0 if f["better"] == "higher" else 1e12
json.dump(r, open(sys.argv[2], "w"))
PY
"$pond" bench --quick --only cpu --compare "$work/doctored.json" > "$work/out" 2> "$work/err"
rc=$?
[ $rc -eq 1 ] || fail "--compare with a doctored baseline: exit $rc, expected 1"
grep -q "cpu.scalar.t1.64 regressed" "$work/err" || fail "--compare does not name cpu.scalar.t1.64: $(cat "$work/err")"
[ "$(grep -c regressed "$work/err")" -eq 1 ] || fail "--compare names other figures: $(cat "$work/err")"
# The same baseline undoctored, with a tolerance no noise reaches: exit 0.
"$pond" bench --quick --only cpu --compare "$work/run.json" --tolerance 99 > "$work/out" 2> "$work/err"
rc=$?
[ $rc -eq 0 ] || fail "--compare with its own baseline at 99 %: exit $rc: $(cat "$work/err")"

# Bad input: exit 2, one line, --json's file untouched.
echo "keep" > "$work/keep.json"
echo "{ not json" > "$work/corrupt.json"
echo '{"schema": "pond-bench/1", "figures": [{"name": "cpu.x"}]}' > "$work/incomplete.json"
for bad in "--only cpu nosuch" "--compare $work/missing.json" "--compare $work/corrupt.json" \
           "--compare $work/incomplete.json" "--tolerance abc" "--tolerance -5" "--frobnicate" \
           "--device no-such-device-anywhere"; do
  "$pond" bench --quick --json "$work/keep.json" $bad > /dev/null 2> "$work/err"
  rc=$?
  [ $rc -eq 2 ] || fail "bench $bad: exit $rc, expected 2"
  [ "$(wc -l < "$work/err")" -eq 1 ] || fail "bench $bad: not one line: $(cat "$work/err")"
  [ "$(cat "$work/keep.json")" = "keep" ] || fail "bench $bad: --json's file was overwritten"
done
[ $failures -eq 0 ] && echo "bench: all checks passed"
exit $failures
