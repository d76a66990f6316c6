#!/bin/sh
# `pond simulate` as a user runs it: a good run writes the contract's STATE.npy and a summary; every
# kind of bad input exits 2 with one stderr line naming the problem and leaves an existing output
# file untouched. Usage: simulate_cli_test.sh PATH/TO/pond WORKDIR
set -u
pond=$1
work=$2
scenes=$(cd "$(dirname "$0")/../../scenes" && pwd)
rm -rf "$work" && mkdir -p "$work" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# A good run: exit 0, the summary, a (50, 50, 6) float32 .npy.
if ! "$pond" simulate --steps 20 --out "$work/state.npy" > "$work/stdout" 2> "$work/stderr"; then
  fail "good run: $(cat "$work/stderr")"
fi
grep -q "state hash" "$work/stdout" || fail "no hash in the summary: $(cat "$work/stdout")"
grep -q "node-steps/s" "$work/stdout" || fail "no speed in the summary"
head -c 128 "$work/state.npy" | grep -q "'descr': '<f4', 'fortran_order': False, 'shape': (50, 50, 6)" ||
  fail "bad STATE.npy header"
[ "$(wc -c < "$work/state.npy")" -eq $((128 + 50 * 50 * 6 * 4)) ] || fail "bad STATE.npy size"
[ -z "$(ls "$work" | grep '\.tmp\.')" ] || fail "temporary file left behind"

printf '{"grid": {"rows": 8, "cols": 8}, "physics": {"dt": 0.3}}' > "$work/ok.json"
printf '{"grid": {"rows": 8, "cols": 8},' > "$work/truncated.json"
printf '{"grid": {"rows": 8, "cols": 8}} trailing' > "$work/malformed.json"
printf '{"grid": {"rows": 8, "cols": 8}, "physics": {"dt": 0.9}}' > "$work/unstable.json"
printf '{"grid": {"rows": 0, "cols": 8}}' > "$work/zero.json"
printf '{"grid": {"rows": 8, "cols": 8}, "physics": {"mass": -4}}' > "$work/mass.json"
printf '{"grid": {"rows": 8, "cols": 8}, "border": "sand"}' > "$work/border.json"
printf '{"grid": {"rows": 8, "cols": 8}, "constraints": [{"kind": "fixed", "rows": [0, 8], "cols": [0, 1]}]}' > "$work/range.json"
printf '{"grid": {"rows": 8, "cols": 8}, "perturbations": [{"row": 4, "col": 4, "radius": 0, "amplitude": 1}]}' > "$work/radius.json"
printf '{"grid": {"rows": 8, "cols": 8}, "perturbations": [{"row": 4, "col": 4, "radius": 1, "amplitude": 1, "mode": "xor"}]}' > "$work/mode.json"
printf '{"grid": {"rows": 8, "cols": 8}, "perturbations": [{"row": 4, "col": 4, "radius": 1, "amplitude": 1e38}]}' > "$work/blowup.json"
mkdir -p "$work/a_folder.json"

expect_bad() {  # expect_bad WORD ARGS...: exit 2, one stderr line containing WORD, output untouched
  word=$1; shift
  printf 'sentinel\n' > "$work/out.npy"
  "$pond" simulate "$@" > "$work/stdout" 2> "$work/stderr"
  code=$?
  lines=$(wc -l < "$work/stderr")
  if [ $code -ne 2 ] || [ "$lines" -ne 1 ] || ! grep -qi -- "$word" "$work/stderr" ||
     [ "$(cat "$work/out.npy")" != sentinel ]; then
    fail "($word): exit $code, stderr: $(cat "$work/stderr"), args: $*"
  fi
}
out="--out $work/out.npy"
# shellcheck disable=SC2086
{
expect_bad "steps" $out
expect_bad "steps" --steps abc $out
expect_bad "steps" --steps -5 $out
expect_bad "steps" --steps 1e99 $out
expect_bad "out" --steps 5
expect_bad "solver" --steps 5 --solver cuda $out
expect_bad "math" --steps 5 --math sloppy $out
expect_bad "threads" --steps 5 --threads 0 $out
expect_bad "unexpected\|not expected\|extra" --steps 5 --frobnicate $out
expect_bad "does not exist" --steps 5 --scene "$work/missing.json" $out
expect_bad "folder" --steps 5 --scene "$work/a_folder.json" $out
expect_bad "invalid JSON" --steps 5 --scene "$work/truncated.json" $out
expect_bad "invalid JSON" --steps 5 --scene "$work/malformed.json" $out
expect_bad "stability bound" --steps 5 --scene "$work/unstable.json" $out
expect_bad "grid.rows" --steps 5 --scene "$work/zero.json" $out
expect_bad "physics.mass" --steps 5 --scene "$work/mass.json" $out
expect_bad "border" --steps 5 --scene "$work/border.json" $out
expect_bad "constraints\[0\].rows" --steps 5 --scene "$work/range.json" $out
expect_bad "radius" --steps 5 --scene "$work/radius.json" $out
expect_bad "mode" --steps 5 --scene "$work/mode.json" $out
expect_bad "perturbations\[0\].amplitude is 1e+38" --steps 50 --scene "$work/blowup.json" $out
expect_bad "output folder" --steps 5 --scene "$work/ok.json" --out "$work/no/such/dir/state.npy"
# A backend this CPU lacks, on any CPU: AVX2 masked out (src/sim/backends.h), or absent (IA-32,
# aarch64); NEON masked out (aarch64) or absent (x86).
export POND_CPU_FEATURES_MASK=avx2
expect_bad "solver avx2" --steps 5 --solver avx2 $out
POND_CPU_FEATURES_MASK=neon
expect_bad "solver neon" --steps 5 --solver neon $out
POND_CPU_FEATURES_MASK=avx2,mmx
expect_bad "POND_CPU_FEATURES_MASK" --steps 5 $out
unset POND_CPU_FEATURES_MASK
}
[ ! -e "$work/no" ] || fail "a missing output folder was created"
# ... while auto falls back to the widest backend left: sse (neon on aarch64, where AVX2 is absent).
POND_CPU_FEATURES_MASK=avx2 "$pond" simulate --steps 5 --scene "$work/ok.json" --out "$work/masked.npy" \
  > "$work/stdout" 2> "$work/stderr" || fail "auto with AVX2 masked: $(cat "$work/stderr")"
grep -q " on \(sse\|neon\) x " "$work/stdout" || fail "auto with AVX2 masked did not run sse or neon: $(cat "$work/stdout")"

# Bodies: --bodies-out writes float32 (B, 6); bad bodies exit 2 naming the key, writing nothing.
"$pond" simulate --steps 40 --scene "$scenes/bodies.json" --out "$work/b_state.npy" --bodies-out "$work/bodies.npy" \
  > "$work/stdout" 2> "$work/stderr" || fail "bodies scene: $(cat "$work/stderr")"
head -c 128 "$work/bodies.npy" | grep -q "'descr': '<f4', 'fortran_order': False, 'shape': (3, 6)" ||
  fail "bodies.npy header: $(head -c 128 "$work/bodies.npy" | tr -d '\0')"
[ "$(stat -c %s "$work/bodies.npy")" -eq $((128 + 3 * 6 * 4)) ] || fail "bodies.npy size"
grep -q "wrote $work/bodies.npy (3 bodies)" "$work/stdout" || fail "no bodies line: $(cat "$work/stdout")"
echo sentinel > "$work/out.npy"
echo sentinel > "$work/bodies_kept.npy"
printf '{"bodies": [{"motion": "floating", "mass": 0, "radius": 2, "position": [5, 1, 5]}]}' > "$work/body_mass.json"
expect_bad "bodies\[0\].mass" --steps 5 --scene "$work/body_mass.json" $out --bodies-out "$work/bodies_kept.npy"
[ "$(cat "$work/bodies_kept.npy")" = sentinel ] || fail "a refused scene clobbered --bodies-out"
printf '{"bodies": [{"motion": "floating", "mass": 3, "radius": 2, "position": [5, 1, 500]}]}' > "$work/body_out.json"
expect_bad "bodies\[0\].position is outside the grid" --steps 5 --scene "$work/body_out.json" $out
printf '{"bodies": [{"motion": "kinematic", "radius": 2, "path": [[9, 1, 0, 1], [3, 2, 0, 2]]}]}' > "$work/body_path.json"
expect_bad "bodies\[0\].path\[1\]" --steps 5 --scene "$work/body_path.json" $out
expect_bad "bodies-out" --steps 5 --scene "$work/ok.json" $out --bodies-out "$work/no/such/dir/b.npy"
for solver in scalar sse avx2 neon; do
  "$pond" simulate --steps 40 --scene "$scenes/bodies.json" --solver $solver --out "$work/bs_$solver.npy" \
    --bodies-out "$work/bb_$solver.npy" > /dev/null 2>&1 || continue  # absent from this build
  cmp -s "$work/bodies.npy" "$work/bb_$solver.npy" || fail "bodies on $solver differ"
  cmp -s "$work/b_state.npy" "$work/bs_$solver.npy" || fail "state with bodies on $solver differs"
done

# The same scene on every backend and thread count gives the same bytes.
for solver in scalar sse avx2 neon; do
  for threads in 1 2; do
    "$pond" simulate --steps 30 --scene "$work/ok.json" --solver $solver --threads $threads \
      --out "$work/s_${solver}_$threads.npy" > /dev/null 2>&1 || continue  # absent from this build
    cmp -s "$work/s_scalar_1.npy" "$work/s_${solver}_$threads.npy" || fail "$solver x $threads differs"
  done
done

if [ $failures -eq 0 ]; then echo "all simulate CLI cases passed"; exit 0; fi
exit 1
