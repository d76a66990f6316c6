#!/bin/sh
# Every parity scene's state hash (water and bodies) from each of this build's CPU solvers, run
# under the emulator, equals the host build's scalar one, line by line (parity_hashes.cpp); each
# mismatch prints both hashes.
# Usage: cross_parity_test.sh HOST_PARITY_HASHES TARGET_PARITY_HASHES SCALE "SOLVER..."
set -u
host=$1 target=$2 scale=$3 solvers=$4
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
"$host" --solver scalar --scale "$scale" > "$work/host" || { echo "FAIL: host parity_hashes: exit $?"; exit 1; }
scenes=$(wc -l < "$work/host")
[ "$scenes" -gt 0 ] || { echo "FAIL: the host printed no scene"; exit 1; }
status=0
for solver in $solvers; do
  "$target" --solver "$solver" --scale "$scale" --threads 2 > "$work/$solver" ||
    { echo "FAIL: $solver: exit $?"; status=1; continue; }
  if cmp -s "$work/host" "$work/$solver"; then
    echo "$solver: $scenes parity scenes, every hash equal to the host's scalar"
  else
    echo "FAIL: $solver differs from the host's scalar (scene steps water bodies):"
    diff "$work/host" "$work/$solver" | sed -n 's/^< /  host:    /p; s/^> /  target:  /p'
    status=1
  fi
done
exit $status
