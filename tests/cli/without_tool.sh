#!/bin/sh
# Runs a command with one tool hidden from PATH, to prove a test does not need it (a minimal Debian
# lacks tools a developer's machine has, e.g. `file`).
# Usage: without_tool.sh TOOL WORKDIR COMMAND [ARGS...]
set -eu
tool=$1 dir=$2/bin
shift 2
rm -rf "$dir" && mkdir -p "$dir"
old_ifs=$IFS
IFS=:
for d in $PATH; do
  [ -d "$d" ] || continue
  for f in "$d"/*; do
    name=${f##*/}
    [ "$name" = "$tool" ] || [ -e "$dir/$name" ] || [ ! -x "$f" ] || ln -s "$f" "$dir/$name"
  done
done
IFS=$old_ifs
PATH=$dir
export PATH
if command -v "$tool" >/dev/null 2>&1; then echo "FAIL: $tool is still on PATH"; exit 1; fi
exec "$@"
