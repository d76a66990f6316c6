#!/bin/sh
# `pond render` from the command line: a good run writes a PNG of the pond right side up (png_probe
# pond: pale sky at the top, blue-green water in the middle, the green shore at the bottom) and
# prints the timing lines (the effects' costs only with --profile); bad input exits 2 with one line
# on stderr naming the problem and leaves an existing output untouched; no Vulkan driver exits 1.
# Usage: render_cli_test.sh PATH/TO/pond PATH/TO/png_probe WORKDIR
set -u
pond=$1
probe=$2
work=$3
rm -rf "$work" && mkdir -p "$work" || exit 1
failures=0

"$pond" render --steps 10 --frames 2 --size 96x64 --out "$work/ok.png" --validation > "$work/stdout" 2> "$work/stderr"
code=$?
if [ $code -ne 0 ] || ! grep -q "ms per frame (median of 2)" "$work/stdout" || ! grep -q "triangles: water" "$work/stdout" ||
   grep -q "effect caustics: " "$work/stdout" ||
   [ "$(head -c 4 "$work/ok.png" | tail -c 3)" != PNG ]; then
  echo "FAIL (good run): exit $code, stdout: $(cat "$work/stdout"), stderr: $(cat "$work/stderr")"
  failures=$((failures + 1))
fi
"$probe" pond "$work/ok.png" > "$work/probe" 2>&1 ||
  { echo "FAIL (good run): the picture is not the pond right side up: $(cat "$work/probe")"; failures=$((failures + 1)); }
# The 1025² scene (issue 30) renders end to end under the validation layer.
scenes=$(dirname "$0")/../../scenes
"$pond" render --scene "$scenes/rain_1025.json" --steps 5 --frames 2 --size 320x180 --out "$work/big.png" --validation \
  > "$work/stdout" 2> "$work/stderr"
code=$?
if [ $code -ne 0 ] || ! grep -q "of a 1025 x 1025 grid" "$work/stdout" || [ "$(head -c 4 "$work/big.png" | tail -c 3)" != PNG ]; then
  echo "FAIL (rain_1025): exit $code, stdout: $(cat "$work/stdout"), stderr: $(cat "$work/stderr")"
  failures=$((failures + 1))
fi
# --profile adds each effect's cost, timed on frozen frames after the picture.
"$pond" render --steps 10 --frames 2 --size 96x64 --out "$work/profiled.png" --profile > "$work/stdout" 2> "$work/stderr"
code=$?
if [ $code -ne 0 ] || ! grep -q "effect caustics: " "$work/stdout"; then
  echo "FAIL (--profile): exit $code, stdout: $(cat "$work/stdout"), stderr: $(cat "$work/stderr")"
  failures=$((failures + 1))
fi

expect_code() {  # expect_code CODE WORD ARGS...: exit CODE, one stderr line containing WORD, output untouched
  want=$1; word=$2; shift 2
  printf 'sentinel\n' > "$work/out.png"
  "$pond" render "$@" > "$work/stdout" 2> "$work/stderr"
  code=$?
  lines=$(wc -l < "$work/stderr")
  if [ $code -ne "$want" ] || [ "$lines" -ne 1 ] || ! grep -qi -- "$word" "$work/stderr" ||
     [ "$(cat "$work/out.png")" != sentinel ]; then
    echo "FAIL ($word): exit $code, stderr: $(cat "$work/stderr"), args: $*"
    failures=$((failures + 1))
  fi
}
out="--out $work/out.png"
printf '{"grid": {"rows": 1}}' > "$work/bad_scene.json"
printf '{"camera": {"eye": [0, 1], "target": [0, 0, 0]}}' > "$work/bad_camera.json"
printf '{"view": {"caustics": "yes"}}' > "$work/bad_caustics.json"
expect_code 2 "beyond the device" --steps 1 --size 20000x64 $out
expect_code 2 "WIDTHxHEIGHT" --steps 1 --size 64 $out
expect_code 2 "--steps" --size 64x64 $out
expect_code 2 "--eye" --steps 1 --size 64x64 --eye 1,2 $out
expect_code 2 "must differ" --steps 1 --size 64x64 --eye 1,2,3 --target 1,2,3 $out
expect_code 2 "--fovy" --steps 1 --size 64x64 --fovy 200 $out
expect_code 2 "--lod-tolerance" --steps 1 --size 64x64 --lod-tolerance -1 $out
expect_code 2 "--solver" --steps 1 --size 64x64 --solver cuda $out
expect_code 2 "grid.rows" --steps 1 --size 64x64 --scene "$work/bad_scene.json" $out
expect_code 2 "camera.eye" --steps 1 --size 64x64 --scene "$work/bad_camera.json" $out
expect_code 2 "view.caustics" --steps 1 --size 64x64 --scene "$work/bad_caustics.json" $out
expect_code 2 "does not exist" --steps 1 --size 64x64 --out "$work/missing/dir/out.png"
VK_ICD_FILENAMES=/nonexistent.json expect_code 1 "vulkan" --steps 1 --size 64x64 $out

[ $failures -eq 0 ] && echo "all render CLI cases passed"
exit $failures
