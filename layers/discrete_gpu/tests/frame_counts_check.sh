#!/bin/sh
# pond's frame under VK_LAYER_POND_discrete_gpu (validation above it), counted by the layer
# ($POND_DISCRETE_GPU_STATS, docs/layer.md): the 257^2 pond with rain (a splash every 4 steps) and
# 8 bodies, GPU solver, every effect on, run for 10 and then 70 frames. Per extra frame the CPU may
# wait for the GPU at most once and invalidate at most 14 * rows * cols + 4 KiB bytes (the
# positions the LOD reads, the bodies): steps, splashes and drawing are never a round trip.
#   frame_counts_check.sh render|demo POND SCENE WORK_DIR   (the layer's environment comes from CTest)
# render: `pond render`. demo: the windowed demo under Xvfb, rain on and a scripted splash in the
# first frames (so both runs have them).
mode=$1 pond=$2 scene=$3 work=$4
mkdir -p "$XDG_RUNTIME_DIR" "$work" && chmod 700 "$XDG_RUNTIME_DIR"
rows=257 cols=257
limit_bytes=$((14 * rows * cols + 4096))
printf 'frame 1 key D\nframe 3 click 400 260\n' > "$work/rain.script"

. "$(dirname "$0")/counted_run.sh"
run() {  # run FRAMES: the layer's counters of one run into $work/FRAMES.json
  if [ "$mode" = demo ]; then
    counted "$1" xvfb-run -a -s "-screen 0 1024x768x24" "$pond" demo --scene "$scene" \
      --frames "$1" --size 640x400 --no-vsync --quiet --validation --script "$work/rain.script"
  else
    counted "$1" "$pond" render --scene "$scene" --steps 4 --frames "$1" --size 320x200 \
      --validation --out "$work/$1.png"
  fi
}

run 10
run 70
waits=$(( $(count 70 host_waits) - $(count 10 host_waits) ))
bytes=$(( $(count 70 bytes_invalidated) - $(count 10 bytes_invalidated) ))
submits=$(( $(count 70 submits) - $(count 10 submits) ))
echo "$mode, 60 extra frames: $waits host waits, $submits submits, $bytes bytes invalidated" \
     "($((waits / 60)) waits and $((bytes / 60)) bytes a frame; limits 1 and $limit_bytes)"
status=0
[ "$waits" -le 60 ] || { echo "FAILED: more than one host wait a frame"; status=1; }
[ "$bytes" -le $((60 * limit_bytes)) ] || { echo "FAILED: more than $limit_bytes bytes invalidated a frame"; status=1; }
exit $status
