#!/usr/bin/env bash
# Compiler CPU seconds of source files in two build trees, compiled alternately with each tree's
# own command (compile_commands.json), to compare build settings on a busy machine (docs/perf.md).
#   scripts/compile_cost.sh BUILD_A BUILD_B FILE...   (FILE: a path under the source tree)
# Prints one line per file (A's seconds, B's) and their sums with B/A. Objects go to a temporary
# directory; the trees are not touched. Needs python3.
set -euo pipefail
if [ $# -lt 3 ]; then
  echo "usage: scripts/compile_cost.sh BUILD_A BUILD_B FILE..." >&2
  exit 2
fi
for tree in "$1" "$2"; do
  if [ ! -f "$tree/compile_commands.json" ]; then
    echo "compile_cost: $tree/compile_commands.json not found (configure that tree first)" >&2
    exit 2
  fi
done
python3 - "$@" << 'PY'
import json, os, shlex, subprocess, sys, tempfile

def commands(tree):
    return {os.path.realpath(e["file"]): e for e in json.load(open(os.path.join(tree, "compile_commands.json")))}

def cpu_seconds(entry, obj):
    args = shlex.split(entry["command"])
    if os.path.basename(args[0]).endswith(".sh") or "ccache" in args[0]:
        args = args[1:]  # a compiler launcher
    args[args.index("-o") + 1] = obj
    before = os.times()
    subprocess.run(args, cwd=entry["directory"], check=True)
    after = os.times()
    return (after.children_user - before.children_user) + (after.children_system - before.children_system)

a, b = commands(sys.argv[1]), commands(sys.argv[2])
total_a = total_b = 0.0
with tempfile.TemporaryDirectory() as tmp:
    obj = os.path.join(tmp, "x.o")
    for name in sys.argv[3:]:
        key = os.path.realpath(name)
        if key not in a or key not in b:
            sys.exit(f"compile_cost: {name} is not compiled in both trees")
        ta, tb = cpu_seconds(a[key], obj), cpu_seconds(b[key], obj)
        total_a += ta
        total_b += tb
        print(f"{name}  {ta:.2f}  {tb:.2f}", flush=True)
print(f"sum  {total_a:.1f}  {total_b:.1f}  ({total_b / total_a:.2f})")
PY
