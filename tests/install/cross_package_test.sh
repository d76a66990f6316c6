#!/bin/sh
# The CPU-only package of a cross build (the arm64 preset): `cpack -G DEB` makes
# pond_VERSION_ARCH.deb for the target's architecture; its Depends are computed by dpkg-shlibdeps
# from the target's own libraries (libc6 and libstdc++6 at least, with versions) and name nothing of
# Vulkan; it holds pond, the scenes and the docs under /usr; the pond extracted from it, run under
# the emulator, prints the built pond's version line.
# Usage: cross_package_test.sh CPACK BUILD_DIR VERSION ARCH BUILT_POND EMULATOR...
set -u
cpack=$1 build=$2 version=$3 arch=$4 built_pond=$5
shift 5
tmp=$(mktemp -d "${TMPDIR:-/tmp}/pond-cross-package-test.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

. "$(dirname "$0")/deb_fields.sh"
make_deb "$cpack" "$build" "pond_${version}_$arch.deb"
[ "$(field Package)" = pond ] || fail "Package: $(field Package)"
[ "$(field Version)" = "$version" ] || fail "Version: $(field Version), expected $version"
[ "$(field Architecture)" = "$arch" ] || fail "Architecture: $(field Architecture), expected $arch"
depends=$(field Depends)
for p in libc6 libstdc++6; do
  echo "$depends" | tr ',' '\n' | grep -q "^ *$p (>= " || fail "Depends has no computed '$p (>= ...)': $depends"
done
for p in libvulkan1 libc6-arm64-cross libstdc++6-arm64-cross; do
  has "$depends" "$p" && fail "Depends names $p: $depends"
done
[ -z "$(field Recommends)" ] || fail "Recommends in a CPU-only package: $(field Recommends)"
dpkg-deb -c "$deb" > "$tmp/contents" || fail "dpkg-deb -c"
for f in usr/bin/pond usr/share/pond/scenes/pool.json usr/share/doc/pond/README.md; do
  grep -q " \./$f\$" "$tmp/contents" || fail "not in the package: /$f"
done

dpkg-deb -x "$deb" "$tmp/root" || fail "dpkg-deb -x"
want=$("$built_pond" --version)
got=$("$@" "$tmp/root/usr/bin/pond" --version 2>&1)
[ "$got" = "$want" ] || fail "packaged --version: '$got', built: '$want'"

[ $failures -eq 0 ] && echo "package: all checks passed: $(basename "$deb"), Depends: $depends"
exit $failures
