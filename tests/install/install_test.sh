#!/bin/sh
# The installed pond (issue 28): `cmake --install` into a temporary prefix outside the source and
# build trees, then, from another directory outside both: `pond --version` prints the build's line,
# `pond render` draws the embedded scene and an installed one (validation on), `pond check` runs
# under the installed discrete-GPU test layer (its manifest's relative library path), and the
# installed files do not name the build tree. The pictures are of the pond right side up (png_probe
# pond: sky at the top, water in the middle, the shore at the bottom).
# Usage: install_test.sh CMAKE BUILD_DIR BUILT_POND PNG_PROBE [VALIDATION_LAYER_DIR]
set -u
cmake=$1 build=$2 built_pond=$3 probe=$4 validation_dir=${5:-}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/pond-install-test.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix pond=$tmp/prefix/bin/pond
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

if ! "$cmake" --install "$build" --prefix "$prefix" > "$tmp/install.log" 2>&1; then
  echo "FAIL: cmake --install: $(cat "$tmp/install.log")"; exit 1
fi
for f in bin/pond share/pond/scenes/default.json share/pond/scenes/pool.json share/doc/pond/README.md \
         share/doc/pond/docs/install.md share/pond/layers/VkLayer_POND_discrete_gpu.json \
         share/pond/layers/libVkLayer_POND_discrete_gpu.so; do
  [ -e "$prefix/$f" ] || fail "not installed: $f"
done
grep -q '"library_path": "./libVkLayer_POND_discrete_gpu.so"' "$prefix/share/pond/layers/VkLayer_POND_discrete_gpu.json" ||
  fail "the layer's manifest does not name its library relative to itself"
grep -rlF "$build/" "$prefix" > "$tmp/naming_build" && fail "installed files name the build tree: $(cat "$tmp/naming_build")"
readelf -d "$prefix/bin/pond" | grep -q "RPATH\|RUNPATH" && fail "the installed pond has a library path: $(readelf -d "$prefix/bin/pond" | grep PATH)"

mkdir "$tmp/elsewhere" && cd "$tmp/elsewhere" || exit 1
version=$("$pond" --version 2>&1)
[ "$version" = "$("$built_pond" --version)" ] || fail "installed --version: '$version'"

for scene in "" "--scene $prefix/share/pond/scenes/pool.json"; do
  # shellcheck disable=SC2086
  "$pond" render $scene --steps 5 --size 64x48 --out frame.png --validation > out 2> err ||
    fail "render ${scene:-(embedded scene)}: exit $?: $(cat err)"
  [ "$(head -c 4 frame.png | tail -c 3)" = PNG ] || fail "render ${scene:-(embedded scene)}: no PNG"
  "$probe" pond frame.png > probe 2>&1 || fail "render ${scene:-(embedded scene)}: not the pond right side up: $(cat probe)"
  rm -f frame.png
done

# `pond check` under the installed layer (validation above it: its messages would go to stdout).
VK_LAYER_PATH="${validation_dir:+$validation_dir:}$prefix/share/pond/layers" \
VK_INSTANCE_LAYERS="${validation_dir:+VK_LAYER_KHRONOS_validation:}VK_LAYER_POND_discrete_gpu" \
  "$pond" check --steps 20 > out 2> err || fail "check under the installed layer: exit $?: $(cat out err)"
[ "$(head -n 1 out)" = "$version" ] || fail "check's report does not start with the version: $(head -n 1 out)"
grep -q "^device: .*(DiscreteGpu)" out || fail "check did not run under the layer: $(grep '^device' out)"
grep -q "^all 7 cases bit-identical$" out || fail "check under the layer: $(cat out)"
grep -qi "validation error\|VUID" out err && fail "validation messages: $(head -c 2000 out)"

[ $failures -eq 0 ] && echo "install: all checks passed ($version)"
exit $failures
