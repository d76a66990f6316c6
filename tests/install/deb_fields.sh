# Sourced by package_test.sh and cross_package_test.sh, with $tmp their scratch directory:
# make_deb CPACK BUILD_DIR FILE runs `cpack -G DEB` into $tmp/out and sets deb to the package FILE
# there (exits with a FAIL line if cpack fails or FILE is not what it made); field NAME prints a
# control field of it; has LIST PACKAGE says whether a Depends-style list names PACKAGE.
make_deb() {
  if ! "$1" -G DEB --config "$2/CPackConfig.cmake" -B "$tmp/out" > "$tmp/cpack.log" 2>&1; then
    echo "FAIL: cpack: $(cat "$tmp/cpack.log")"; exit 1
  fi
  deb=$tmp/out/$3
  [ -f "$deb" ] || { echo "FAIL: no $3, only: $(ls "$tmp/out")"; exit 1; }
}
field() { dpkg-deb -f "$deb" "$1"; }
has() { echo "$1" | tr ',' '\n' | sed 's/^ *//; s/ *(.*//' | grep -qx "$2"; }
