#!/bin/sh
# `pond lod` on bad input: every case must exit 2, print one line on stderr naming the problem,
# and leave an existing output file untouched. A good run's TRIS.npy must tile the grid and keep
# every left-out node in view within the tolerance (tris_check: the independent mesh checker of
# tests/lod), and leave nodes out: fewer triangles than the full mesh's.
# Usage: lod_cli_test.sh PATH/TO/pond PATH/TO/tris_check WORKDIR
# ($POND_TEST_EMULATOR, if set, runs tris_check: the IA-32 build's emulator.)
set -u
pond=$1
checker=$2
work=$3
rm -rf "$work" && mkdir -p "$work" || exit 1
failures=0

# A hand-made .npy: header padded to 128 bytes (header length 118 = octal 166), then the payload.
npy() {  # npy FILE DESCR SHAPE PAYLOAD-PRINTF-FORMAT
  dict="{'descr': '$2', 'fortran_order': False, 'shape': $3, }"
  while [ ${#dict} -lt 117 ]; do dict="$dict "; done
  { printf '\223NUMPY\001\000\166\000'; printf '%s\n' "$dict"; printf "$4"; } > "$1"
}
zeros96=''
i=0; while [ $i -lt 24 ]; do zeros96="$zeros96\\000\\000\\000\\000"; i=$((i + 1)); done
nan_then_zeros="\\000\\000\\300\\177"
i=1; while [ $i -lt 24 ]; do nan_then_zeros="$nan_then_zeros\\000\\000\\000\\000"; i=$((i + 1)); done

# The default scene 40 steps after its splash: rings to keep in detail near the camera.
"$pond" simulate --steps 40 --out "$work/state.npy" > /dev/null || { echo "simulate failed"; exit 1; }
printf 'not numpy at all\n' > "$work/text.npy"
npy "$work/int.npy" '<i4' '(2, 2, 6)' "$zeros96"
npy "$work/shape.npy" '<f4' '(4, 6)' "$zeros96"
npy "$work/thin.npy" '<f4' '(1, 4, 6)' "$zeros96"
npy "$work/nan.npy" '<f4' '(2, 2, 6)' "$nan_then_zeros"

good="--eye 24,30,-20 --target 24,0,24 --fovy 60 --size 640x480 --tolerance 1"
expect_bad() {  # expect_bad WORD ARGS...: exit 2, one stderr line containing WORD, output untouched
  word=$1; shift
  printf 'sentinel\n' > "$work/out.npy"
  "$pond" lod "$@" --out "$work/out.npy" > "$work/stdout" 2> "$work/stderr"
  code=$?
  lines=$(wc -l < "$work/stderr")
  if [ $code -ne 2 ] || [ "$lines" -ne 1 ] || ! grep -qi -- "$word" "$work/stderr" ||
     [ "$(cat "$work/out.npy")" != sentinel ]; then
    echo "FAIL ($word): exit $code, stderr: $(cat "$work/stderr"), args: $*"
    failures=$((failures + 1))
  fi
}

# shellcheck disable=SC2086
{
expect_bad "not a .npy" --state "$work/text.npy" $good
expect_bad "float32" --state "$work/int.npy" $good
expect_bad "float32" --state "$work/shape.npy" $good
expect_bad "2 x 2" --state "$work/thin.npy" $good
expect_bad "non-finite" --state "$work/nan.npy" $good
expect_bad "missing.npy" --state "$work/missing.npy" $good
expect_bad "tolerance" --state "$work/state.npy" --eye 24,30,-20 --target 24,0,24 --fovy 60 --size 640x480 --tolerance 0
expect_bad "tolerance" --state "$work/state.npy" --eye 24,30,-20 --target 24,0,24 --fovy 60 --size 640x480 --tolerance -1
expect_bad "fovy" --state "$work/state.npy" --eye 24,30,-20 --target 24,0,24 --fovy 0 --size 640x480 --tolerance 1
expect_bad "fovy" --state "$work/state.npy" --eye 24,30,-20 --target 24,0,24 --fovy 180 --size 640x480 --tolerance 1
expect_bad "size" --state "$work/state.npy" --eye 24,30,-20 --target 24,0,24 --fovy 60 --size 0x480 --tolerance 1
expect_bad "size" --state "$work/state.npy" --eye 24,30,-20 --target 24,0,24 --fovy 60 --size big --tolerance 1
expect_bad "differ" --state "$work/state.npy" --eye 1,2,3 --target 1,2,3 --fovy 60 --size 640x480 --tolerance 1
expect_bad "eye" --state "$work/state.npy" --eye 1,2 --target 1,2,3 --fovy 60 --size 640x480 --tolerance 1
expect_bad "repeat" --state "$work/state.npy" $good --repeat 0
expect_bad "repeat" --state "$work/state.npy" $good --repeat many
expect_bad "state" --eye 24,30,-20 --target 24,0,24 --fovy 60 --size 640x480 --tolerance 1
# A bad CPU feature mask is named as itself, not as a fault of the state the builder was reading.
export POND_CPU_FEATURES_MASK=bogus
expect_bad "^pond: POND_CPU_FEATURES_MASK: unknown CPU feature 'bogus'" --state "$work/state.npy" $good
unset POND_CPU_FEATURES_MASK
}

# And the good case writes a (T, 3) uint32 TRIS.npy and one summary line.
"$pond" lod --state "$work/state.npy" $good --out "$work/tris.npy" > "$work/stdout" 2> "$work/stderr" ||
  { echo "FAIL: good run: $(cat "$work/stderr")"; failures=$((failures + 1)); }
grep -q "triangles" "$work/stdout" || { echo "FAIL: no summary line"; failures=$((failures + 1)); }
head -c 128 "$work/tris.npy" | grep -q "'<u4'.*, 3)" || { echo "FAIL: TRIS.npy header"; failures=$((failures + 1)); }
# What the triangles are: the contract, checked independently, at the run's camera and tolerance,
# and fewer than the 50 x 50 grid's 4802.
check_tris() {  # check_tris TRIS.npy EYE TARGET FOVY SIZE TOLERANCE
  # shellcheck disable=SC2086
  $POND_TEST_EMULATOR "$checker" "$work/state.npy" "$@" > "$work/check" 2>&1 ||
    { echo "FAIL: $1 breaks the contract: $(cat "$work/check")"; failures=$((failures + 1)); return; }
  cat "$work/check"
  t=$(sed -n 's/^tris_check: \([0-9]*\) triangles.*/\1/p' "$work/check")
  [ -n "$t" ] && [ "$t" -lt 4802 ] && [ "$t" -gt 2 ] ||
    { echo "FAIL: $1 has ${t:-no} triangles, expected between 2 and the full mesh's 4802"; failures=$((failures + 1)); }
}
POND_TEST_EMULATOR=${POND_TEST_EMULATOR:-}
check_tris "$work/tris.npy" 24,30,-20 24,0,24 60 640x480 1
# A close, grazing view at a quarter pixel.
"$pond" lod --state "$work/state.npy" --eye 10,3,12 --target 30,0,30 --fovy 50 --size 800x600 --tolerance 0.25 \
  --out "$work/near.npy" > /dev/null 2> "$work/stderr" || { echo "FAIL: near run: $(cat "$work/stderr")"; failures=$((failures + 1)); }
check_tris "$work/near.npy" 10,3,12 30,0,30 50 800x600 0.25

# --repeat N reports the median of the N - 1 warm builds in the same line.
"$pond" lod --state "$work/state.npy" $good --repeat 3 --out "$work/tris3.npy" > "$work/stdout" 2> "$work/stderr" ||
  { echo "FAIL: --repeat run: $(cat "$work/stderr")"; failures=$((failures + 1)); }
grep -q "built in [0-9.]* ms (median of 2 warm builds" "$work/stdout" ||
  { echo "FAIL: --repeat line: $(cat "$work/stdout")"; failures=$((failures + 1)); }
cmp -s "$work/tris.npy" "$work/tris3.npy" || { echo "FAIL: --repeat changed TRIS.npy"; failures=$((failures + 1)); }

[ $failures -eq 0 ] && echo "all pond lod bad-input cases passed"
exit $failures
