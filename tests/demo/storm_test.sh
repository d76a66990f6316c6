#!/bin/sh
# A swapchain storm: the demo under a virtual X server with the validation layer, resized on every
# one of 200 frames (sizes from 64x48 to 1280x720, a 1x1 window among them) while vsync is toggled
# every 7 frames and splashes keep the water busy. It must exit 0 with no validation message
# (the demo exits non-zero on any) and leave a final screenshot of the scene; the process's peak
# RSS must not grow with the number of recreations: the sizes repeat every 50 frames, so a 50-frame
# storm reaches the same sizes (and the same peak, bar allocator noise) as the 200-frame one, which
# recreates the swapchain four times as often. glibc's dynamic mmap threshold is pinned for the
# runs: otherwise each freed swapchain-sized block raises it, later blocks come from the heap, and
# the peak grows with fragmentation (measured: +21 MiB from 50 to 400 frames, against +3 MiB
# pinned), which is the allocator's choice, not a leak. Leaked Vulkan objects are reported by the
# validation layer when the device is destroyed.
# Then minimize and restore, twice, under a window manager (twm, tests/demo/twmrc; an X server
# alone ignores iconify requests): the demo must see the minimized frames, draw nothing in them,
# and come back to the same swapchain path. The demo starts once twm manages the screen: twm
# creates its own windows (info, size) after taking the root's redirection, so the root having
# children is the condition waited for (xwininfo, at most 20 s).
# Usage: storm_test.sh PATH/TO/pond WORKDIR
set -u
pond=$1
work=$2
rm -rf "$work" && mkdir -p "$work" || exit 1
# Failures are counted in a file: run() is called in a command substitution (a subshell).
: > "$work/failures"
fail() { echo "FAIL: $*" | tee -a "$work/failures" >&2; }

storm() {  # storm FRAMES SCRIPT
  frames=$1 out=$2
  : > "$out"
  f=0
  while [ $f -lt "$frames" ]; do
    p=$((f % 50))
    w=$(( 64 + (p * 397) % 1217 )); h=$(( 48 + (p * 211) % 673 ))
    [ $((f % 50)) -eq 25 ] && { w=1; h=1; }
    echo "frame $f resize $w $h" >> "$out"
    [ $((f % 7)) -eq 3 ] && echo "frame $f key F3" >> "$out"
    [ $((f % 11)) -eq 5 ] && echo "frame $f click $((w / 2)) $((h / 2))" >> "$out"
    f=$((f + 1))
  done
  echo "frame $((frames - 1)) resize 320 200" >> "$out"
}

run() {  # run FRAMES NAME: prints the peak RSS in KiB
  storm "$1" "$work/$2.script"
  MALLOC_MMAP_THRESHOLD_=131072 xvfb-run -a -s "-screen 0 1400x900x24" /usr/bin/time -f "%M" -o "$work/$2.rss" \
    "$pond" demo --frames "$1" --size 320x200 --script "$work/$2.script" --validation --quiet \
    --screenshot "$work/$2.png" > "$work/$2.out" 2>&1
  rc=$?
  [ $rc -eq 0 ] || fail "$2: exit $rc: $(tail -n 5 "$work/$2.out")"
  [ "$(wc -c < "$work/$2.png" 2> /dev/null || echo 0)" -gt 1000 ] || fail "$2: no screenshot"
  tail -n 1 "$work/$2.rss"
}

short=$(run 50 short)
long=$(run 200 long)
echo "peak RSS: 50-frame storm ${short} KiB, 200-frame storm ${long} KiB"
case "$short$long" in *[!0-9]*|"") fail "could not read the peak RSS ($short, $long)" ;; *)
  [ "$long" -le $((short + 8192)) ] || fail "peak RSS grew by more than 8 MiB: $short -> $long KiB" ;;
esac

# Minimize and restore, with a splash in between.
printf 'frame 5 minimize\nframe 15 restore\nframe 20 click 160 100\nframe 25 minimize\nframe 30 restore\n' \
  > "$work/minimize.script"
here=$(dirname "$0")
xvfb-run -a -s "-screen 0 1400x900x24" sh -c "twm -f '$here/twmrc' > '$work/twm.log' 2>&1 & wm=\$!; until=\$((\$(date +%s) + 20));
  until xwininfo -root -children | grep -q '^ *[1-9][0-9]* child'; do
    [ \$(date +%s) -le \$until ] || { echo 'twm did not start within 20 s' > '$work/minimize.out'; kill \$wm; exit 1; }
    sleep 0.05
  done
  '$pond' demo --frames 40 --size 320x200 --script '$work/minimize.script' --validation \
    --screenshot '$work/minimize.png' > '$work/minimize.out' 2>&1; rc=\$?; kill \$wm; exit \$rc"
rc=$?
[ $rc -eq 0 ] || fail "minimize: exit $rc: $(tail -n 5 "$work/minimize.out")"
grep -q "frames minimized" "$work/minimize.out" || fail "minimize: the demo never saw its window minimized"
[ "$(wc -c < "$work/minimize.png" 2> /dev/null || echo 0)" -gt 1000 ] || fail "minimize: no screenshot"
grep "frames minimized" "$work/minimize.out"

if [ ! -s "$work/failures" ]; then echo "swapchain storm passed"; exit 0; fi
exit 1
