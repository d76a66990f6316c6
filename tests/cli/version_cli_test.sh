#!/bin/sh
# `pond --version` and the help text (issue 28). --version: exit 0, nothing on stderr, one line
#   pond VERSION[ (git DESCRIBE)], CPU backends NAME..., VULKAN
# with the project's VERSION, "(git ...)" when the sources are a git checkout and git is here, the
# CPU backends of this build as given (scalar sse avx2 avx512 on x86-64, scalar sse on IA-32,
# scalar neon on aarch64) and VULKAN as given. Help: every command's and
# option's description starts with a capital letter or a symbol, never a lower-case word.
# Usage: version_cli_test.sh POND SOURCE_DIR VERSION VULKAN BACKENDS
#   (VULKAN: "Vulkan headers X.Y.Z" or "no Vulkan"; BACKENDS: e.g. "scalar neon")
set -u
pond=$1 source_dir=$2 version=$3 vulkan=$4 backends=$5
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
err=$(mktemp) || exit 1
trap 'rm -f "$err" "$err.bad"' EXIT

line=$("$pond" --version 2> "$err")
rc=$?
[ $rc -eq 0 ] || fail "--version: exit $rc"
[ ! -s "$err" ] || fail "--version wrote to stderr: $(cat "$err")"
[ "$(printf '%s\n' "$line" | wc -l)" -eq 1 ] || fail "--version printed more than one line: $line"
v=$(printf '%s' "$version" | sed 's/\./\\./g')
printf '%s\n' "$line" |
  grep -Eqx "pond $v( \(git [A-Za-z0-9._+-]+\))?, CPU backends $backends, $vulkan" ||
  fail "--version: '$line' is not 'pond $version[ (git ...)], CPU backends $backends, $vulkan'"
if command -v git > /dev/null && git -C "$source_dir" rev-parse --git-dir > /dev/null 2>&1 &&
   [ "$(cd "$(git -C "$source_dir" rev-parse --show-toplevel)" && pwd -P)" = "$(cd "$source_dir" && pwd -P)" ]; then
  printf '%s\n' "$line" | grep -q " (git [^)]*), " || fail "built from a checkout, but no (git ...): $line"
fi

# Help: CLI11 starts every description (and its continuation) in column 31; never lower-case there.
for cmd in "" demo simulate render lod tree check; do
  # shellcheck disable=SC2086
  "$pond" $cmd --help > "$err" 2>&1 || fail "pond $cmd --help: exit $?"
  grep -E '^.{28}  [a-z]' "$err" | sed "s/^/pond $cmd --help: lower-case description: /" > "$err.bad"
  [ ! -s "$err.bad" ] || fail "$(cat "$err.bad")"
  rm -f "$err.bad"
done

[ $failures -eq 0 ] && echo "version: $line"
exit $failures
