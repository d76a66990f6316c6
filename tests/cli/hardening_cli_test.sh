#!/bin/sh
# Hostile but fair input to the CPU commands (issue 60), by class: every case exits 2 with one
# stderr line that names what is wrong (the key, the flag, the file) and holds no control byte,
# and leaves the output files untouched. Usage: hardening_cli_test.sh PATH/TO/pond WORKDIR
set -u
pond=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
work=$2
rm -rf "$work" && mkdir -p "$work" || exit 1
failures=0
fail() { printf 'FAIL: %s\n' "$*"; failures=$((failures + 1)); }
nl='
'
esc=$(printf '\033')

# expect_bad TEXT ARGS...: exit 2, one stderr line containing TEXT (a fixed string), no control
# byte in it, the sentinel outputs untouched.
expect_bad() {
  text=$1; shift
  for f in out.npy bodies.npy out.png; do printf 'sentinel\n' > "$work/$f"; done
  "$pond" "$@" > "$work/stdout" 2> "$work/stderr"
  code=$?
  lines=$(wc -l < "$work/stderr")
  kept=1
  for f in out.npy bodies.npy out.png; do [ "$(cat "$work/$f")" = sentinel ] || kept=0; done
  if [ $code -ne 2 ] || [ "$lines" -ne 1 ] || ! grep -qF -- "$text" "$work/stderr" || [ $kept -ne 1 ] ||
     tr -d '\n' < "$work/stderr" | LC_ALL=C grep -q '[[:cntrl:]]'; then
    fail "($text): exit $code, stderr: $(cat "$work/stderr"), args: $*"
  fi
}
scene() { printf '%s' "$2" > "$work/$1.json"; }  # scene NAME JSON
out="--out $work/out.npy"

# User text is shown escaped on one line: keys, values, paths, flags and words typed by the user.
scene key_newline '{"grid": {"rows": 8, "cols": 8, "ro\nws": 3}}'
expect_bad 'grid.ro\nws is not a known key' simulate --steps 1 --scene "$work/key_newline.json" $out
scene key_escape '{"physics": {"\u001b[2J\u001b[31mred": 1}}'
expect_bad 'physics.\x1b[2J\x1b[31mred is not a known key' simulate --steps 1 --scene "$work/key_escape.json" $out
scene value_newline '{"border": "sa\nnd\u0000"}'
expect_bad "border is 'sa\\nnd\\0', expected" simulate --steps 1 --scene "$work/value_newline.json" $out
expect_bad "file '$work/no\\nsuch\\x1b[31m.json' does not exist" simulate --steps 1 --scene "$work/no${nl}such${esc}[31m.json" $out
expect_bad "output folder '$work/no\\ndir' does not exist" simulate --steps 1 --out "$work/no${nl}dir/x.npy"
expect_bad 'not expected: a\x0ab' simulate --steps 1 $out "a${nl}b"
expect_bad "--size 'big\\x1b[5m' must be WIDTHxHEIGHT" lod --state "$work/x.npy" --eye 1,1,1 --target 0,0,0 --fovy 45 \
  --size "big${esc}[5m" --tolerance 1 $out
expect_bad "--eye '1,2,3\\n' must be three finite numbers" lod --state "$work/x.npy" --eye "1,2,3${nl}" --target 0,0,0 \
  --fovy 45 --size 8x8 --tolerance 1 $out
expect_bad "--depth '7\\n' must be an integer" tree --depth "7$nl" --seed 1 --out "$work/tree"

# Every numeric flag in pond's words: a whole number in digits, a finite number in its range.
expect_bad "--steps: must be a whole number from 0 to 1099511627776 in decimal digits, not '1e3'" simulate --steps 1e3 $out
expect_bad "--steps: must be a whole number" simulate --steps 99999999999999999999 $out
expect_bad "--steps: must be a whole number" simulate --steps -1 $out
expect_bad "--steps: must be a whole number" simulate --steps 0x10 $out
expect_bad "--threads: must be a whole number from 1 to 1024" simulate --steps 1 --threads 1e1 $out
expect_bad "--repeat: must be a whole number from 1 to 100000" lod --state "$work/x.npy" --eye 1,1,1 --target 0,0,0 \
  --fovy 45 --size 8x8 --tolerance 1 --repeat 2.5 $out
expect_bad "--tolerance: must be a number of pixels > 0, at most 1e6, not 'nan'" lod --state "$work/x.npy" --eye 1,1,1 \
  --target 0,0,0 --fovy 45 --size 8x8 --tolerance nan $out
expect_bad "--fovy: must be a number of degrees from 0.01 to 179.99, not 'inf'" lod --state "$work/x.npy" --eye 1,1,1 \
  --target 0,0,0 --fovy inf --size 8x8 --tolerance 1 $out
expect_bad "--lod-tolerance: must be a number of pixels >= 0 (0 = the full mesh), at most 1e6, not 'nan'" \
  render --steps 1 --size 8x8 --lod-tolerance nan --out "$work/out.png"
expect_bad "--lod-tolerance: must be a number of pixels >= 0" render --steps 1 --size 8x8 --lod-tolerance -0.5 --out "$work/out.png"
expect_bad "--frames: must be a whole number from 1 to 1000000" render --steps 1 --frames 1e3 --size 8x8 --out "$work/out.png"
expect_bad "--fovy: must be a number of degrees" render --steps 1 --fovy 1e-300 --size 8x8 --out "$work/out.png"
expect_bad "--frames: must be a whole number from 1 to 1000000000" demo --frames 1e3
expect_bad "--steps: must be a whole number from 1 to 10000000" check --steps 1e3
# 010 is ten steps, not octal eight.
"$pond" simulate --steps 010 --out "$work/ten.npy" > "$work/stdout" 2>&1 || fail "--steps 010: $(cat "$work/stdout")"
grep -q "^simulated 10 steps" "$work/stdout" || fail "--steps 010 is not ten steps: $(head -1 "$work/stdout")"

# A key given twice in one object is refused with its path (nlohmann would keep the last).
scene twice '{"grid": {"rows": 10, "rows": 20}}'
expect_bad "twice.json: grid.rows is given twice" simulate --steps 1 --scene "$work/twice.json" $out
scene twice_body '{"bodies": [{"motion": "floating", "radius": 2, "mass": 3, "position": [5, 1, 5], "mass": 4}]}'
expect_bad "bodies[0].mass is given twice" simulate --steps 1 --scene "$work/twice_body.json" $out

# Every number of a scene within the range where its arithmetic stays finite and meaningful, in the
# units it is used in; the message names the key and shows the digits that put it outside.
refuse_scene() {  # refuse_scene TEXT JSON
  scene range "$2"
  expect_bad "$1" simulate --steps 3 --scene "$work/range.json" $out --bodies-out "$work/bodies.npy"
}
refuse_scene 'physics.body_drag is 1e+39, outside [0, 1e+06]' '{"physics": {"body_drag": 1e39}}'
refuse_scene 'physics.water_density is 1e+39' '{"physics": {"water_density": 1e39}}'
refuse_scene 'physics.mass is 1e-300' '{"physics": {"mass": 1e-300}}'
refuse_scene 'grid.spacing is 1e+300' '{"grid": {"spacing": 1e300}}'
refuse_scene 'grid.spacing is 1e-300' '{"grid": {"spacing": 1e-300}}'
refuse_scene 'wind.direction_deg is 1e+100' '{"wind": {"direction_deg": 1e100}}'
refuse_scene 'perturbations[0].radius is 1e+09 (1e+09 grid spacings)' \
  '{"perturbations": [{"row": 25, "col": 25, "radius": 1e9, "amplitude": 1}]}'
refuse_scene 'perturbations[0].amplitude is 1e+38' '{"perturbations": [{"row": 25, "col": 25, "radius": 2, "amplitude": 1e38}]}'
refuse_scene 'tree.height is 1e+300' \
  '{"constraints": [{"kind": "fixed", "rows": [20, 24], "cols": [30, 34]}], "tree": {"height": 1e300}}'
refuse_scene 'bodies[0].path[1] has y 1e+300' \
  '{"bodies": [{"motion": "kinematic", "radius": 2, "path": [[0, 10, 0, 10], [10, 10, 1e300, 10]]}]}'
refuse_scene 'bodies[0].density is 100.00001;' \
  '{"bodies": [{"motion": "floating", "radius": 2, "density": 100.00001, "position": [10, 0, 10]}]}'
refuse_scene 'camera.eye has a coordinate that is 1e+160' '{"camera": {"eye": [1e160, 1e160, 1e160], "target": [0, 0, 0]}}'
refuse_scene 'basin.floor_depth is 1e-300' '{"basin": {"floor_depth": 1e-300}}'

# Cameras float view matrices cannot hold are refused naming the flag; a target a denormal away
# from the eye gives the triangles of the same direction at a sane scale.
"$pond" simulate --steps 5 --out "$work/state.npy" > /dev/null || fail "simulate for lod"
view="--state $work/state.npy --fovy 45 --size 640x480 --tolerance 1"
lod() { "$pond" lod $view "$@"; }
expect_bad "--eye has a coordinate 1e+160, outside [-1e+15, 1e+15]" lod $view --eye 1e160,1e160,1e160 --target 25,0,25 $out
expect_bad "--target has a coordinate -1e+16" lod $view --eye 1,1,1 --target 0,-1e16,0 $out
expect_bad "--target must differ from --eye" lod $view --eye 3,4,5 --target 3,4,5 $out
for pair in "0,0,0 5e-324,0,0 1,0,0" "0,10,0 1e-310,10,-1e-310 1,10,-1" "7,3,7 7,3,7.000000000000001 7,3,8"; do
  set -- $pair
  lod --eye "$1" --target "$2" --out "$work/tiny.npy" > /dev/null 2>&1 || fail "lod --eye $1 --target $2"
  lod --eye "$1" --target "$3" --out "$work/sane.npy" > /dev/null 2>&1 || fail "lod --eye $1 --target $3"
  cmp -s "$work/tiny.npy" "$work/sane.npy" || fail "lod --eye $1 --target $2: not the triangles of --target $3"
done

# Two outputs of one command are compared by what they name, not by their text; a name too long for
# the file system is refused up front, like a missing folder.
mkdir -p "$work/real_dir" && ln -sfn real_dir "$work/link_dir" && ln -sfn out.npy "$work/alias.npy"
expect_bad "--bodies-out '$work/./out.npy' names the same file as --out '$work/out.npy'" \
  simulate --steps 1 $out --bodies-out "$work/./out.npy"
expect_bad "names the same file as --out" simulate --steps 1 $out --bodies-out "$work/real_dir/../out.npy"
expect_bad "names the same file as --out" simulate --steps 1 $out --bodies-out "$work/alias.npy"
expect_bad "names the same file as --out" simulate --steps 1 --out "$work/real_dir/s.npy" --bodies-out "$work/link_dir/s.npy"
(cd "$work" && "$pond" simulate --steps 1 --out same.npy --bodies-out ./same.npy > stdout 2> stderr)
[ $? -eq 2 ] && [ ! -e "$work/same.npy" ] || fail "--out same.npy --bodies-out ./same.npy: $(cat "$work/stderr")"
printf 'sentinel\n' > "$work/t.vertices.npy" && ln -sfn t.vertices.npy "$work/t.parents.npy"
expect_bad "--out's parents '$work/t.parents.npy' names the same file as --out's vertices" tree --depth 3 --seed 1 --out "$work/t"
long=$(printf '%0250d' 0)
expect_bad "output file name '${long}.npy' has 254 bytes; its folder takes at most 223 (NAME_MAX 255" \
  simulate --steps 1 --out "$work/$long.npy"
expect_bad "has 256 bytes" lod --state "$work/state.npy" --eye 1,1,1 --target 0,0,0 --fovy 45 --size 8x8 --tolerance 1 \
  --out "$work/${long}ab.npy"
expect_bad "has 243 bytes" tree --depth 3 --seed 1 --out "$work/$(printf '%0230d' 0)"
expect_bad ".vertices.npy.partial." tree --depth 3 --seed 1 --out "$work/$(printf '%0210d' 0)"  # its partial name
expect_bad "has 254 bytes" render --steps 1 --size 8x8 --out "$work/$long.png"
# A folder that exists, but with the name the whole path passes PATH_MAX (4096).
deep=$(cd "$work" && i=0 && while [ $i -lt 80 ]; do mkdir -p "d$(printf '%048d' $i)" && cd "d$(printf '%048d' $i)" || exit 1; i=$((i + 1)); done && pwd)
expect_bad "bytes is longer than the" simulate --steps 1 --out "$deep/$(printf '%0100d' 0).npy"

# A flag given twice, in pond's words.
expect_bad "--steps is given 2 times; give it once" simulate --steps 1 --steps 2 $out

# A number the JSON parser cannot hold as a double names its key, as every other number does.
scene overflow '{"grid": {"rows": 8, "cols": 8}, "physics": {"dt": 1e3080}}'
expect_bad "physics.dt is a number beyond a double's range" simulate --steps 1 --scene "$work/overflow.json" $out
scene overflow_array '{"bodies": [{"motion": "floating", "position": [1, -1e999, 2]}]}'
expect_bad "bodies[0].position[1] is a number beyond" simulate --steps 1 --scene "$work/overflow_array.json" $out

# An output that names the run's own input (however spelt) would overwrite what it reads.
scene own_input '{"grid": {"rows": 8, "cols": 8}}'
cp "$work/own_input.json" "$work/own_input.keep"
expect_bad "--out '$work/./own_input.json' names the same file as its input --scene" \
  simulate --steps 1 --scene "$work/own_input.json" --out "$work/./own_input.json"
expect_bad "--bodies-out '$work/own_input.json' names the same file as its input --scene" \
  simulate --steps 1 --scene "$work/own_input.json" $out --bodies-out "$work/own_input.json"
cmp -s "$work/own_input.json" "$work/own_input.keep" || fail "the scene named as an output was changed"
"$pond" simulate --steps 2 --scene "$work/own_input.json" $out --checkpoint "$work/own.ckpt" > /dev/null 2>&1 ||
  fail "a checkpoint to resume from was not written"
expect_bad "--out '$work/real_dir/../own.ckpt' names the same file as its input --resume" \
  simulate --steps 1 --resume "$work/own.ckpt" --out "$work/real_dir/../own.ckpt"
"$pond" simulate --steps 1 --resume "$work/own.ckpt" --checkpoint "$work/./own.ckpt" $out > /dev/null 2>&1 ||
  fail "--checkpoint over the --resume file it went on from is refused"
"$pond" simulate --steps 1 --scene "$work/own_input.json" $out > /dev/null 2>&1 && cp "$work/out.npy" "$work/state.npy"
expect_bad "--out '$work/state.npy' names the same file as its input --state" \
  lod --state "$work/state.npy" --eye 4,6,20 --target 4,0,4 --fovy 45 --size 64x64 --tolerance 1 --out "$work/state.npy"

# A signal ends a read that would never end by itself: a file with no end, a FIFO without a writer.
for input in /dev/zero fifo; do
  [ "$input" = fifo ] && { rm -f "$work/fifo"; mkfifo "$work/fifo"; input=$work/fifo; }
  printf 'sentinel\n' > "$work/out.npy"
  "$pond" simulate --steps 1 --scene "$input" $out > /dev/null 2> "$work/stderr" &
  pid=$!
  # Until it blocks there: /dev/zero open (it reads on), or the FIFO's open waiting for a writer.
  n=0
  until ls -l /proc/$pid/fd 2> /dev/null | grep -q -- "-> /dev/zero" ||
        [ "$(cat /proc/$pid/wchan 2> /dev/null)" = wait_for_partner ] || [ $n -ge 500 ]; do
    n=$((n + 1)); sleep 0.01
  done
  kill -INT $pid
  waited=0
  while kill -0 $pid 2> /dev/null && [ $waited -lt 50 ]; do sleep 0.1; waited=$((waited + 1)); done
  if kill -0 $pid 2> /dev/null; then kill -KILL $pid; fail "SIGINT did not end the read of $input within 5 s"; fi
  wait $pid
  code=$?
  [ $code -eq 130 ] && grep -q "interrupted by SIGINT while" "$work/stderr" && [ "$(cat "$work/out.npy")" = sentinel ] ||
    fail "SIGINT reading $input: exit $code, $(cat "$work/stderr")"
done

# A file size limit (ulimit -f: SIGXFSZ ignored, the write fails): exit 1, one line naming the
# output the user asked for, no temporary file, an old output untouched.
for cmd in simulate tree; do
  rm -rf "$work/limit" && mkdir -p "$work/limit" && printf 'sentinel\n' > "$work/limit/out.npy"
  if [ $cmd = simulate ]; then  # the default 50 x 50 pond: 60 kB against a limit of 8 blocks
    name=new.npy
    (ulimit -f 8 && "$pond" simulate --steps 1 --out "$work/limit/new.npy") > /dev/null 2> "$work/stderr"
  else
    name=t.vertices.npy
    (ulimit -f 8 && "$pond" tree --depth 8 --seed 1 --out "$work/limit/t") > /dev/null 2> "$work/stderr"
  fi
  code=$?
  [ $code -eq 1 ] && [ "$(wc -l < "$work/stderr")" -eq 1 ] && grep -q "cannot write '$work/limit/$name'" "$work/stderr" ||
    fail "$cmd under ulimit -f: exit $code, $(cat "$work/stderr")"
  [ "$(ls "$work/limit")" = out.npy ] || fail "$cmd under ulimit -f left: $(ls "$work/limit" | tr '\n' ' ')"
done

# The demo's bad input, refused before any window (so without a display): script numbers finite and
# bounded, control bytes, frame numbers, screenshots that could never be taken, window sizes.
if "$pond" --version | grep -q "Vulkan headers"; then
  script() { printf "$2" > "$work/$1.script"; }  # script NAME PRINTF-FORMAT
  script nan 'frame 1 move nan nan\n'
  expect_bad "nan.script line 1: x 'nan' is outside [-65536, 65536]" demo --frames 3 --script "$work/nan.script"
  script inf 'frame 0 key H\nframe 1 click inf inf\n'
  expect_bad "inf.script line 2: x 'inf' is outside" demo --frames 3 --script "$work/inf.script"
  script far 'frame 1 drag left 10 10 10 1e30\n'
  expect_bad "far.script line 1: y1 '1e30' is outside" demo --frames 3 --script "$work/far.script"
  script wheel 'frame 1 scroll 1e30\n'
  expect_bad "wheel.script line 1: scroll amount '1e30' is outside [-100, 100]" demo --frames 3 --script "$work/wheel.script"
  script huge 'frame 1 scroll 1e999\n'
  expect_bad "huge.script line 1: scroll amount '1e999' is outside" demo --frames 3 --script "$work/huge.script"
  script nul 'frame 1 move 1\0002 3\n'
  expect_bad 'nul.script line 1: control byte \0 at column 15' demo --frames 3 --script "$work/nul.script"
  script frame 'frame 99999999999999999999 key H\n'
  expect_bad "frame number '99999999999999999999' is out of range" demo --frames 3 --script "$work/frame.script"
  script late "frame 1 key H\nframe 50 screenshot $work/late.png\n"
  expect_bad "late.script line 2: screenshot at frame 50 is past the last frame (--frames 10" \
    demo --frames 10 --script "$work/late.script"
  expect_bad "--screenshot must name a file" demo --frames 3 --screenshot ""
  expect_bad "--screenshot must name a file" --frames 3 --screenshot ""
  script nodir "frame 1 screenshot $work/no_dir/s.png\n"
  expect_bad "nodir.script line 1: screenshot: output folder '$work/no_dir' does not exist" demo --frames 3 --script "$work/nodir.script"
  script nodir_save "frame 0 key H\nframe 1 save $work/no_dir/s.ckpt\n"
  expect_bad "nodir_save.script line 2: save: output folder '$work/no_dir' does not exist" demo --frames 3 --script "$work/nodir_save.script"
  expect_bad "--screenshot saves the last frame of --frames N: give --frames" demo --screenshot "$work/s.png"
  expect_bad "--size 65536x1: a window takes at most 32767 pixels a side" demo --frames 3 --size 65536x1
  # The demo's outputs by what they name: two script screenshots, a script's and --screenshot.
  printf 'frame 1 screenshot %s\nframe 2 screenshot %s\n' "$work/s.png" "$work/./s.png" > "$work/shots.script"
  expect_bad "--script line 2: screenshot '$work/./s.png' names the same file as --script line 1" \
    demo --frames 3 --script "$work/shots.script"
  printf 'frame 1 screenshot %s\n' "$work/s.png" > "$work/shot.script"
  expect_bad "names the same file as --screenshot" demo --frames 3 --script "$work/shot.script" --screenshot "$work/real_dir/../s.png"
  # A trailing comment is no bad input: the run goes on to need a display (exit 1), not exit 2.
  script comment 'frame 1 scroll 2   # zoom in\nframe 2 key H # help\n# a whole line\n'
  env -u DISPLAY -u WAYLAND_DISPLAY "$pond" demo --frames 3 --script "$work/comment.script" > /dev/null 2> "$work/stderr"
  [ $? -eq 1 ] && grep -q "needs a display" "$work/stderr" || fail "a trailing comment: $(cat "$work/stderr")"
fi

if [ $failures -eq 0 ]; then echo "all hardening CLI cases passed"; exit 0; fi
exit 1
