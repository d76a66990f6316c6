#!/bin/sh
# `pond check` as a user runs it: exit 0, the version line first, a row per case saying "identical",
# the device and its float controls, the identity line; bad input exits 2 with one line.
# Usage: check_cli_test.sh PATH/TO/pond
set -u
pond=$1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
out=$("$pond" check --steps 300 ${POND_DEVICE:+--device "$POND_DEVICE"} 2> /tmp/check_err.$$)
rc=$?
[ $rc -eq 0 ] || fail "exit $rc: $out $(cat /tmp/check_err.$$)"
for c in paper_pond vertical_border_islands denormal_decay every_perturbation_kind odd_width_17x33; do
  echo "$out" | grep -q "^$c .* 300  identical$" || fail "no identical row for $c"
done
echo "$out" | grep -q "^float controls, 32-bit: shaderDenormPreserveFloat32 " || fail "no float controls line"
echo "$out" | grep -q "^bit-identity with the CPU: " || fail "no identity line"
echo "$out" | grep -q "^all 7 cases bit-identical$" || fail "no summary line"
[ "$(echo "$out" | head -n 1)" = "$("$pond" --version)" ] || fail "the report does not start with the version line"
for bad in "--steps 0" "--steps x" "--device no-such-device-anywhere" "--frobnicate"; do
  "$pond" check $bad > /dev/null 2> /tmp/check_err.$$
  rc=$?
  [ $rc -eq 2 ] || fail "check $bad: exit $rc, expected 2"
  [ "$(wc -l < /tmp/check_err.$$)" -eq 1 ] || fail "check $bad: not one line: $(cat /tmp/check_err.$$)"
done
rm -f /tmp/check_err.$$
[ $failures -eq 0 ] && echo "check: all checks passed"
exit $failures
