#!/bin/sh
# Checkpoints as a user makes them (docs/checkpoints.md): on a scene with rain, wind ripples, a
# tree's wind and floating and kinematic bodies, a run of N steps and a run of K steps saved and
# resumed for N - K more give the same state hash, on each solver given and across them; so do a
# chain of resumed runs, --checkpoint-every, and a run stopped by SIGINT and resumed. Bad input
# (a corrupt checkpoint, --scene beside --resume, ...) exits 2 with one line and writes nothing.
#   checkpoint_cli_test.sh POND WORK SCENE SOLVER...   (SOLVER: scalar, sse, avx2, avx512, gpu, auto)
# Every other CPU backend this pond has (`pond --version`) is tried too, saving for the first
# solver given and resuming what that one saved.
set -u
pond=$1 work=$2 scene=$3
shift 3
solvers=$* extras=
for b in $("$pond" --version | sed -n 's/.*CPU backends \([a-z0-9 ]*\).*/\1/p'); do
  case " $solvers " in *" $b "*) ;; *) extras="$extras $b" ;; esac
done
echo "solvers: $solvers; backends beside them:$extras"
rm -rf "$work" && mkdir -p "$work" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
hash_of() { sed -n 's/^state hash //p' "$1"; }
run() {  # run NAME ARGS...: pond simulate ARGS, stdout and stderr into NAME.out / NAME.err
  name=$1; shift
  "$pond" simulate "$@" > "$work/$name.out" 2> "$work/$name.err" || fail "$name: exit $?: $(cat "$work/$name.err")"
}

# The uninterrupted runs' hashes: the same on every solver.
run full_auto --scene "$scene" --steps 300 --out "$work/full.npy"
expected=$(hash_of "$work/full_auto.out")
[ -n "$expected" ] || fail "no hash from the uninterrupted run"
for s in $solvers; do
  run "full_$s" --scene "$scene" --steps 300 --solver "$s" --out "$work/full_$s.npy"
  [ "$(hash_of "$work/full_$s.out")" = "$expected" ] || fail "uninterrupted on $s: $(hash_of "$work/full_$s.out") != $expected"
done

# K steps saved, N - K resumed: every saving solver with every resuming one.
for a in $solvers; do
  run "save_$a" --scene "$scene" --steps 120 --solver "$a" --out "$work/part.npy" --checkpoint "$work/$a.ckpt"
  grep -q "checkpoint at step 120" "$work/save_$a.out" || fail "save on $a: no checkpoint line: $(cat "$work/save_$a.out")"
  for b in $solvers; do
    run "resume_${a}_$b" --resume "$work/$a.ckpt" --steps 180 --solver "$b" --out "$work/r.npy"
    got=$(hash_of "$work/resume_${a}_$b.out")
    [ "$got" = "$expected" ] || fail "saved on $a, resumed on $b: $got != $expected"
  done
done

# The other backends: uninterrupted, saved and resumed on the first solver, and the other way.
first=$(echo "$solvers" | cut -d' ' -f1)
for x in $extras; do
  run "full_$x" --scene "$scene" --steps 300 --solver "$x" --out "$work/full_$x.npy"
  [ "$(hash_of "$work/full_$x.out")" = "$expected" ] || fail "uninterrupted on $x: $(hash_of "$work/full_$x.out") != $expected"
  run "save_$x" --scene "$scene" --steps 120 --solver "$x" --out "$work/part.npy" --checkpoint "$work/$x.ckpt"
  run "resume_${x}_$first" --resume "$work/$x.ckpt" --steps 180 --solver "$first" --out "$work/r.npy"
  [ "$(hash_of "$work/resume_${x}_$first.out")" = "$expected" ] || fail "saved on $x, resumed on $first"
  run "resume_${first}_$x" --resume "$work/$first.ckpt" --steps 180 --solver "$x" --out "$work/r.npy"
  [ "$(hash_of "$work/resume_${first}_$x.out")" = "$expected" ] || fail "saved on $first, resumed on $x"
done

# A chain: 100, then 50 more saved over the same file, then 150 more.
last=$(echo "$solvers" | tr ' ' '\n' | tail -n 1)
run chain1 --scene "$scene" --steps 100 --solver "$first" --out "$work/c.npy" --checkpoint "$work/chain.ckpt"
run chain2 --resume "$work/chain.ckpt" --steps 50 --solver "$last" --out "$work/c.npy" --checkpoint "$work/chain.ckpt"
run chain3 --resume "$work/chain.ckpt" --steps 150 --solver "$first" --out "$work/c.npy"
[ "$(hash_of "$work/chain3.out")" = "$expected" ] || fail "a chain of three runs: $(hash_of "$work/chain3.out") != $expected"

# --checkpoint-every: the saves on the way change nothing, and the last is at the end.
run every --scene "$scene" --steps 300 --solver "$last" --out "$work/e.npy" --checkpoint "$work/every.ckpt" --checkpoint-every 70
[ "$(hash_of "$work/every.out")" = "$expected" ] || fail "--checkpoint-every changed the run"
run every0 --resume "$work/every.ckpt" --steps 0 --out "$work/e0.npy"
[ "$(hash_of "$work/every0.out")" = "$expected" ] || fail "the last --checkpoint-every save is not the end's state"

# Killed outright (SIGKILL) after a save on the way: that save is whole and resumes to the end's bits.
long=100000
run long --scene "$scene" --steps $long --out "$work/long.npy"
long_hash=$(hash_of "$work/long.out")
"$pond" simulate --scene "$scene" --steps $long --out "$work/k.npy" --checkpoint "$work/kill.ckpt" \
  --checkpoint-every 5000 > /dev/null 2>&1 &
pid=$!
n=0
while [ ! -f "$work/kill.ckpt" ] && kill -0 $pid 2> /dev/null && [ $n -lt 6000 ]; do n=$((n + 1)); sleep 0.01; done
kill -KILL $pid 2> /dev/null
wait $pid 2> /dev/null
if [ -f "$work/kill.ckpt" ]; then
  run kill0 --resume "$work/kill.ckpt" --steps 0 --out "$work/k0.npy"
  at=$(sed -n 's/^resumed at step \([0-9]*\) .*/\1/p' "$work/kill0.out")
  [ -n "$at" ] && [ $((at % 5000)) -eq 0 ] || fail "the save on the way is at step '$at', not a multiple of 5000"
  run kill1 --resume "$work/kill.ckpt" --steps $((long - at)) --out "$work/k1.npy"
  [ "$(hash_of "$work/kill1.out")" = "$long_hash" ] || fail "resumed after SIGKILL: $(hash_of "$work/kill1.out") != $long_hash"
else
  fail "no checkpoint on the way before the run ended"
fi
[ -z "$(ls "$work" | grep '\.tmp\.')" ] || fail "a temporary file was left: $(ls "$work")"

# SIGINT (and SIGTERM) during a long run: exit 130 (143), the checkpoint at the last step done, the
# message says how to go on, --out untouched; resuming as it says gives the uninterrupted bits.
for sig in INT TERM; do
  rm -f "$work/sig.ckpt"
  printf 'sentinel\n' > "$work/sig.npy"
  "$pond" simulate --scene "$scene" --steps $long --out "$work/sig.npy" --checkpoint "$work/sig.ckpt" \
    --checkpoint-every 5000 > "$work/sig.out" 2> "$work/sig.err" &
  pid=$!
  n=0
  while [ ! -f "$work/sig.ckpt" ] && kill -0 $pid 2> /dev/null && [ $n -lt 6000 ]; do n=$((n + 1)); sleep 0.01; done
  kill -$sig $pid
  wait $pid
  code=$?
  want=130
  [ $sig = TERM ] && want=143
  [ $code -eq $want ] || fail "SIG$sig: exit $code, not $want: $(cat "$work/sig.err")"
  [ "$(wc -l < "$work/sig.err")" -eq 1 ] || fail "SIG$sig: not one line: $(cat "$work/sig.err")"
  [ "$(cat "$work/sig.npy")" = sentinel ] || fail "SIG$sig: --out was written"
  rest=$(sed -n 's/.*--resume [^ ]* --steps \([0-9]*\) .*/\1/p' "$work/sig.err")
  if [ -n "$rest" ]; then
    run "sig_$sig" --resume "$work/sig.ckpt" --steps "$rest" --out "$work/s.npy"
    [ "$(hash_of "$work/sig_$sig.out")" = "$long_hash" ] || fail "SIG$sig then resume: $(hash_of "$work/sig_$sig.out") != $long_hash"
  else
    fail "SIG$sig: the message does not say how to resume: $(cat "$work/sig.err")"
  fi
done

# Bad input: exit 2, one line naming the problem, --out untouched.
expect_bad() {  # expect_bad WORD ARGS...
  word=$1; shift
  printf 'sentinel\n' > "$work/out.npy"
  "$pond" simulate "$@" > "$work/bad.out" 2> "$work/bad.err"
  code=$?
  if [ $code -ne 2 ] || [ "$(wc -l < "$work/bad.err")" -ne 1 ] || ! grep -qi -- "$word" "$work/bad.err" ||
     [ "$(cat "$work/out.npy")" != sentinel ]; then
    fail "($word): exit $code, stderr: $(cat "$work/bad.err"), args: $*"
  fi
}
ck=$work/$first.ckpt
size=$(wc -c < "$ck")
head -c $((size - 1)) "$ck" > "$work/truncated.ckpt"
head -c 30 "$ck" > "$work/header_only.ckpt"
cp "$ck" "$work/flipped.ckpt"
printf 'X' | dd of="$work/flipped.ckpt" bs=1 seek=$((size - 5)) conv=notrunc 2> /dev/null
{ cat "$ck"; printf 'more'; } > "$work/trailing.ckpt"
{ printf 'NOTPOND!'; tail -c +9 "$ck"; } > "$work/magic.ckpt"
cp "$ck" "$work/version.ckpt"
printf '\007' | dd of="$work/version.ckpt" bs=1 seek=8 conv=notrunc 2> /dev/null
cp "$ck" "$work/layout.ckpt"
printf '\001' | dd of="$work/layout.ckpt" bs=1 seek=16 conv=notrunc 2> /dev/null
cp "$ck" "$work/order.ckpt"
printf '\001\002\003\004' | dd of="$work/order.ckpt" bs=1 seek=12 conv=notrunc 2> /dev/null
out="--out $work/out.npy"
# shellcheck disable=SC2086
{
expect_bad "truncated" --resume "$work/truncated.ckpt" --steps 5 $out
expect_bad "truncated" --resume "$work/header_only.ckpt" --steps 5 $out
expect_bad "checksum" --resume "$work/flipped.ckpt" --steps 5 $out
expect_bad "after its end" --resume "$work/trailing.ckpt" --steps 5 $out
expect_bad "not a pond checkpoint" --resume "$work/magic.ckpt" --steps 5 $out
expect_bad "not a pond checkpoint" --resume "$scene" --steps 5 $out
expect_bad "version" --resume "$work/version.ckpt" --steps 5 $out
expect_bad "layout" --resume "$work/layout.ckpt" --steps 5 $out
expect_bad "byte order" --resume "$work/order.ckpt" --steps 5 $out
expect_bad "does not exist" --resume "$work/missing.ckpt" --steps 5 $out
expect_bad "scene" --resume "$ck" --scene "$scene" --steps 5 $out
expect_bad "checkpoint-every" --scene "$scene" --steps 5 --checkpoint-every 2 $out
expect_bad "names the same file as --out" --scene "$scene" --steps 5 --checkpoint "$work/out.npy" $out
expect_bad "names the same file as --out" --scene "$scene" --steps 5 --checkpoint "$work/./out.npy" $out
expect_bad "does not exist" --scene "$scene" --steps 5 --checkpoint "$work/no/such/folder.ckpt" $out
}
cmp -s "$ck" "$work/$first.ckpt" || fail "a bad run changed the checkpoint it read"

if [ $failures -eq 0 ]; then echo "all checkpoint CLI cases passed ($solvers)"; exit 0; fi
echo "$failures checkpoint CLI case(s) failed"
exit 1
