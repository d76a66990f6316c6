#!/bin/sh
# The Debian package (issue 28): `cpack -G DEB` makes pond_VERSION_ARCH.deb; its control fields
# (dpkg-deb -f) name the package, version and architecture, Depends has libvulkan1 (computed by
# dpkg-shlibdeps) and Recommends mesa-vulkan-drivers; it holds pond, the scenes, the docs and the
# test layer under /usr; the pond extracted from it (dpkg-deb -x) prints the build's version line and
# renders a packaged scene from a directory outside the source and build trees: the pond right side
# up (png_probe pond).
# Usage: package_test.sh CPACK BUILD_DIR VERSION BUILT_POND PNG_PROBE
set -u
cpack=$1 build=$2 version=$3 built_pond=$4 probe=$5
tmp=$(mktemp -d "${TMPDIR:-/tmp}/pond-package-test.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

arch=$(dpkg --print-architecture)
. "$(dirname "$0")/deb_fields.sh"
make_deb "$cpack" "$build" "pond_${version}_$arch.deb"
[ "$(field Package)" = pond ] || fail "Package: $(field Package)"
[ "$(field Version)" = "$version" ] || fail "Version: $(field Version), expected $version"
[ "$(field Architecture)" = "$arch" ] || fail "Architecture: $(field Architecture)"
has "$(field Depends)" libvulkan1 || fail "Depends has no libvulkan1: $(field Depends)"
has "$(field Recommends)" mesa-vulkan-drivers || fail "Recommends has no mesa-vulkan-drivers: $(field Recommends)"
dpkg-deb -c "$deb" > "$tmp/contents" || fail "dpkg-deb -c"
for f in usr/bin/pond usr/share/pond/scenes/pool.json usr/share/doc/pond/README.md \
         usr/share/pond/layers/VkLayer_POND_discrete_gpu.json usr/share/pond/layers/libVkLayer_POND_discrete_gpu.so; do
  grep -q " \./$f\$" "$tmp/contents" || fail "not in the package: /$f"
done

dpkg-deb -x "$deb" "$tmp/root" || fail "dpkg-deb -x"
mkdir "$tmp/elsewhere" && cd "$tmp/elsewhere" || exit 1
pond=$tmp/root/usr/bin/pond
[ "$("$pond" --version)" = "$("$built_pond" --version)" ] || fail "packaged --version: '$("$pond" --version 2>&1)'"
"$pond" render --scene "$tmp/root/usr/share/pond/scenes/pool.json" --steps 5 --size 64x48 --out frame.png \
  --validation > out 2> err || fail "packaged render: exit $?: $(cat err)"
[ "$(head -c 4 frame.png | tail -c 3)" = PNG ] || fail "packaged render: no PNG"
"$probe" pond frame.png > probe 2>&1 || fail "packaged render: not the pond right side up: $(cat probe)"

[ $failures -eq 0 ] && echo "package: all checks passed: $(basename "$deb"), Depends: $(field Depends)"
exit $failures
