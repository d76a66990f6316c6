#!/bin/sh
# The windowed demo with hostile but fair input (issue 60), under a virtual X server with the
# validation layer on:
#  - a window wider than the device can draw: exit 2 and one line, as `pond render` refuses the size,
#    no Vulkan rule broken (a validation message would be a second line);
#  - a requested screenshot the run never reaches (ESCAPE before its frame): exit 1 and one line
#    naming it, nothing written;
#  - a script's screenshot on the last frame beside --screenshot: both written, the same picture.
# Usage: hardening_demo_test.sh PATH/TO/pond WORKDIR
set -u
pond=$1
work=$2
rm -rf "$work" && mkdir -p "$work" || exit 1
failures=0
fail() { printf 'FAIL: %s\n' "$*"; failures=$((failures + 1)); }
demo() {  # demo ARGS...: the demo under xvfb-run, validation on; sets rc, stderr in $work/stderr
  xvfb-run -a "$pond" demo --quiet --validation "$@" > "$work/stdout" 2> "$work/stderr"
  rc=$?
}

for size in 20000x100 100x16385; do
  demo --frames 3 --size $size --screenshot "$work/wide.png"
  { [ $rc -eq 2 ] && [ "$(wc -l < "$work/stderr")" -eq 1 ] && grep -q "size $size is beyond the device's limits" "$work/stderr" &&
    [ ! -e "$work/wide.png" ]; } || fail "--size $size: exit $rc, $(cat "$work/stderr")"
done

printf 'frame 1 key ESCAPE\nframe 5 screenshot %s\n' "$work/never.png" > "$work/escape.script"
demo --frames 10 --script "$work/escape.script"
{ [ $rc -eq 1 ] && [ "$(wc -l < "$work/stderr")" -eq 1 ] &&
  grep -q "no screenshot '$work/never.png' (--script line 2, frame 5): the demo ended after 1 frame" "$work/stderr" &&
  [ ! -e "$work/never.png" ]; } || fail "ESCAPE before a script's screenshot: exit $rc, $(cat "$work/stderr")"
printf 'frame 2 key ESCAPE\n' > "$work/quit.script"
demo --frames 10 --script "$work/quit.script" --screenshot "$work/final.png"
{ [ $rc -eq 1 ] && grep -q "no screenshot '$work/final.png' (--screenshot, frame 9)" "$work/stderr" &&
  [ ! -e "$work/final.png" ]; } || fail "ESCAPE before --screenshot's frame: exit $rc, $(cat "$work/stderr")"

printf 'frame 1 key H # the help overlay\nframe 5 screenshot %s\n' "$work/script.png" > "$work/last.script"
demo --frames 6 --size 320x200 --script "$work/last.script" --screenshot "$work/last.png"
[ $rc -eq 0 ] || fail "a script's screenshot on the last frame: exit $rc, $(cat "$work/stderr")"
cmp -s "$work/script.png" "$work/last.png" || fail "the last frame's two screenshots are not the same picture"

if [ $failures -eq 0 ]; then echo "all hardening demo cases passed"; exit 0; fi
exit 1
