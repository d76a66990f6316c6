#!/bin/sh
# pond under VK_LAYER_POND_discrete_gpu presenting the Vulkan minimum maxTexelBufferElements (65536):
# a 257^2 grid's state needs more texels than such a device can view, so `pond simulate --solver gpu`
# exits 1 with a line naming the limit and writes nothing; a 64^2 grid fits and runs. A signed or
# overflowing value is refused by the layer (a line, lavapipe's limit kept), never read as 65536.
#   texel_limit_check.sh POND SCENES_DIR WORK_DIR      (the layer's environment comes from CTest)
pond=$1 scenes=$2 work=$3
mkdir -p "$XDG_RUNTIME_DIR" "$work" && chmod 700 "$XDG_RUNTIME_DIR"
rm -f "$work"/*.npy
export POND_DISCRETE_GPU_MAX_TEXEL_BUFFER_ELEMENTS=65536
status=0
"$pond" simulate --scene "$scenes/ripples_257.json" --steps 1 --solver gpu --out "$work/big.npy" 2> "$work/err"
rc=$?
if [ $rc -eq 1 ] && grep -q "maxTexelBufferElements is 65536" "$work/err" && [ ! -e "$work/big.npy" ]; then
  echo "ok: 257^2 refused: $(cat "$work/err")"
else
  echo "FAILED: 257^2 with 65536 texels: exit $rc, $(cat "$work/err")"; status=1
fi
"$pond" simulate --steps 1 --solver gpu --out "$work/small.npy" 2> "$work/err"
rc=$?
if [ $rc -eq 0 ] && [ -s "$work/small.npy" ]; then echo "ok: the default grid runs"
else echo "FAILED: the default grid: exit $rc, $(cat "$work/err")"; status=1; fi
for bad in -18446744073709486080 +65536 99999999999999999999999 ' 65536'; do
  POND_DISCRETE_GPU_MAX_TEXEL_BUFFER_ELEMENTS=$bad "$pond" simulate --scene "$scenes/ripples_257.json" --steps 1 \
    --solver gpu --out "$work/bad.npy" 2> "$work/err"
  rc=$?
  if [ $rc -eq 0 ] && grep -q "MAX_TEXEL_BUFFER_ELEMENTS=$bad is not a number >= 65536; ignored" "$work/err"; then
    echo "ok: '$bad' refused by the layer"
  else
    echo "FAILED: '$bad': exit $rc, $(cat "$work/err")"; status=1
  fi
done
exit $status
