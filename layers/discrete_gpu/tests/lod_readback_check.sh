#!/bin/sh
# The LOD's readback on a discrete GPU (issue 30), counted by VK_LAYER_POND_discrete_gpu
# ($POND_DISCRETE_GPU_STATS, docs/layer.md): `pond render` of the 1025^2 rain pond, GPU solver,
# 200 steps in, then 3 and then 8 frames at 1280x720. Per extra frame the host may invalidate at
# most 10 % of the state (24 bytes a node): the tile bounds, the bodies and the nodes the LOD reads,
# not the whole displacements (12 bytes a node). Bringing blocks the last frame did not read costs
# a wait, with the corners of the leaves the ranges accepted in the same copy: at most 12 waits in
# the 5 frames (the frame's own 5, a round of blocks in most, the odd round of corners left after).
# The LOD must have refined (blocks read): else the bound says nothing.
#   lod_readback_check.sh POND SCENE WORK_DIR   (the layer's environment comes from CTest)
pond=$1 scene=$2 work=$3
mkdir -p "$XDG_RUNTIME_DIR" "$work" && chmod 700 "$XDG_RUNTIME_DIR"
rows=1025 cols=1025
limit_bytes=$((24 * rows * cols / 10))

. "$(dirname "$0")/counted_run.sh"
run() {  # run FRAMES: the layer's counters of one run into $work/FRAMES.json
  counted "$1" "$pond" render --scene "$scene" --steps 200 --frames "$1" --size 1280x720 --validation \
    --out "$work/$1.png"
}

run 3
run 8
waits=$(( $(count 8 host_waits) - $(count 3 host_waits) ))
bytes=$(( $(count 8 bytes_invalidated) - $(count 3 bytes_invalidated) ))
triangles=$(sed -n 's/^triangles: water \([0-9]*\) .*/\1/p' "$work/8.out")
echo "1025^2 rain, 5 extra frames: $waits host waits, $bytes bytes invalidated ($((bytes / 5)) a frame," \
     "$((bytes / 5 * 1000 / (24 * rows * cols))) per mille of the state; limit $limit_bytes); $triangles water triangles"
status=0
[ "${triangles:-0}" -ge 1000 ] || { echo "FAILED: the LOD drew ${triangles:-no} triangles: too few to refine blocks"; status=1; }
[ "$bytes" -le $((5 * limit_bytes)) ] || { echo "FAILED: more than $limit_bytes bytes invalidated a frame"; status=1; }
[ "$bytes" -gt 0 ] || { echo "FAILED: nothing read back"; status=1; }
[ "$waits" -le 12 ] || { echo "FAILED: more than 12 host waits in 5 frames"; status=1; }
exit $status
