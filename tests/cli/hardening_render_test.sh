#!/bin/sh
# `pond render` with hostile but fair input (issue 60), on the test device: a camera far out is
# refused naming the flag; a target a denormal away from the eye, and a sun given at 1e200 or
# 1e-200, draw the very picture of the same direction at a sane scale; --profile never prints a
# negative cost. Usage: hardening_render_test.sh PATH/TO/pond WORKDIR
set -u
pond=$1
work=$2
rm -rf "$work" && mkdir -p "$work" || exit 1
failures=0
fail() { printf 'FAIL: %s\n' "$*"; failures=$((failures + 1)); }
render() {  # render OUT ARGS...: a small frame of the default scene; fails the test on an error
  name=$1; shift
  "$pond" render --steps 2 --size 96x64 --out "$work/$name.png" "$@" > "$work/stdout" 2> "$work/stderr" ||
    fail "render $*: $(cat "$work/stderr")"
}

printf 'sentinel\n' > "$work/kept.png"
for eye in 1e160,1e160,1e160 1e16,0,0 nan,0,0; do
  "$pond" render --steps 2 --size 96x64 --eye "$eye" --target 25,0,25 --out "$work/kept.png" > /dev/null 2> "$work/stderr"
  code=$?
  { [ $code -eq 2 ] && [ "$(wc -l < "$work/stderr")" -eq 1 ] && grep -q -- "--eye" "$work/stderr" &&
    [ "$(cat "$work/kept.png")" = sentinel ]; } || fail "--eye $eye: exit $code, $(cat "$work/stderr")"
done

render sane --eye 0,10,0 --target 1,10,-1
render denormal --eye 0,10,0 --target 1e-310,10,-1e-310
cmp -s "$work/sane.png" "$work/denormal.png" || fail "a target a denormal away draws another picture"
render far_ok --eye 1e15,1e15,1e15 --target 25,0,25 --validation

for sun in "1, 1, 0" "1e200, 1e200, 0" "1e-200, 1e-200, 0" "4e-320, 4e-320, 0"; do
  printf '{"lighting": {"sun": [%s]}}' "$sun" > "$work/sun.json"
  render "sun_${sun%%,*}" --scene "$work/sun.json"
  cmp -s "$work/sun_1.png" "$work/sun_${sun%%,*}.png" || fail "sun [$sun] draws another picture than [1, 1, 0]"
done

"$pond" render --steps 2 --frames 2 --size 96x64 --out "$work/profiled.png" --profile > "$work/stdout" 2> "$work/stderr" ||
  fail "--profile: $(cat "$work/stderr")"
[ "$(grep -c "^effect " "$work/stdout")" -eq 5 ] || fail "--profile: not one line for each of the five effects: $(cat "$work/stdout")"
if grep "^effect " "$work/stdout" | grep -q ": -"; then fail "--profile printed a negative cost: $(cat "$work/stdout")"; fi
# Two frames read no pass time back (each slot's queries are read when it comes round again): said,
# not an empty heading.
grep -q "^GPU pass times: none read back yet" "$work/stdout" ||
  grep -q "^GPU pass times: none, the device has no timestamps" "$work/stdout" ||
  fail "--profile --frames 2: the pass times line: $(grep "GPU pass" "$work/stdout")"

if [ $failures -eq 0 ]; then echo "all hardening render cases passed"; exit 0; fi
exit 1
