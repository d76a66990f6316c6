#!/bin/sh
# vulkaninfo under VK_LAYER_POND_discrete_gpu (VK_LAYER_PATH and VK_INSTANCE_LAYERS come from CTest):
# a discrete GPU, no memory type both device-local and host-visible, no coherent host-visible
# type, no shaderInt64, the 256-byte atom, and the denormal setting both ways. Exit 77: skipped.
command -v vulkaninfo >/dev/null 2>&1 || { echo "vulkaninfo is not installed: skipped"; exit 77; }
mkdir -p "$XDG_RUNTIME_DIR" && chmod 700 "$XDG_RUNTIME_DIR"
out=$(vulkaninfo 2>/dev/null) || { echo "vulkaninfo failed"; exit 1; }
status=0
expect() {  # expect <what> <extended regex>
  if printf '%s\n' "$out" | grep -Eq "$2"; then echo "ok: $1"; else echo "FAILED: $1 (no line matches '$2')"; status=1; fi
}
expect "a discrete GPU" 'deviceType += PHYSICAL_DEVICE_TYPE_DISCRETE_GPU'
expect "no shaderInt64" '^[[:space:]]*shaderInt64 += false'
expect "nonCoherentAtomSize 256" 'nonCoherentAtomSize += 0x0*100$'
expect "denormals preserved by default" 'shaderDenormPreserveFloat32 += true'
# Each memoryTypes[i] block lists its MEMORY_PROPERTY_* flags, one per line, before "usable for".
if printf '%s\n' "$out" | awk '
  /memoryTypes\[[0-9]+\]:/ { inside = 1; dl = hv = hc = 0; name = $1; next }
  inside && /MEMORY_PROPERTY_DEVICE_LOCAL_BIT/ { dl = 1 }
  inside && /MEMORY_PROPERTY_HOST_VISIBLE_BIT/ { hv = 1 }
  inside && /MEMORY_PROPERTY_HOST_COHERENT_BIT/ { hc = 1 }
  inside && /usable for/ {
    inside = 0; types++
    if (dl && hv) { print "  " name " is DEVICE_LOCAL and HOST_VISIBLE"; bad = 1 }
    if (hv && hc) { print "  " name " is HOST_VISIBLE and HOST_COHERENT"; bad = 1 }
  }
  END { exit (bad || types == 0) }'; then
  echo "ok: no memory type both device-local and host-visible, none host-visible and coherent"
else
  echo "FAILED: memory types (above)"; status=1
fi
out=$(POND_DISCRETE_GPU_DENORM_PRESERVE=0 vulkaninfo 2>/dev/null) || { echo "vulkaninfo failed"; exit 1; }
expect "POND_DISCRETE_GPU_DENORM_PRESERVE=0 withdraws denormal preservation" 'shaderDenormPreserveFloat32 += false'
exit $status
