#!/usr/bin/env bash
# Draws the solver's speed by backend and grid size from a `pond bench --json` file: one cluster of
# bars per grid size, one bar per CPU backend and thread count, then the GPU solver's exact and fast
# math, in M node-steps/s (each bar the median of the run's samples). Needs python3 and gnuplot
# (gnuplot-nox: scripts/setup.sh).
#   scripts/plot_solver_speed.sh [BENCH.json] [OUT.png]
#   (defaults: bench/results/epyc-zen5-2-cores.json, docs/solver_speed.png)
set -euo pipefail
cd "$(dirname "$0")/.."
json=${1:-bench/results/epyc-zen5-2-cores.json}
out=${2:-docs/solver_speed.png}
data=$(mktemp)
trap 'rm -f "$data" "$data.title" "$data.title.n"' EXIT
# Rows: grid sizes; columns: the CPU's series in the order pond bench ran them, then the GPU's.
python3 - "$json" "$data" "$data.title" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
series, sizes, value = [], [], {}
for f in r["figures"]:
    parts = f["name"].split(".")
    if parts[0] == "cpu":      # cpu.<backend>.t<threads>.<size>
        label = "%s x%s" % (parts[1], parts[2][1:])
    elif parts[0] == "gpu":    # gpu.<math>.<size>
        label = "GPU %s" % parts[1]
    else:
        continue
    size = parts[-1]
    if label not in series: series.append(label)
    if size not in sizes: sizes.append(size)
    value[(label, size)] = f["median"] / 1e6
series.sort(key=lambda label: label.startswith("GPU"))  # the CPU's first (stable), then the GPU's
if not series:
    sys.exit("%s: no solver figures (run pond bench without --only, or with --only cpu gpu)" % sys.argv[1])
with open(sys.argv[2], "w") as out:
    out.write("size " + " ".join('"%s"' % s for s in series) + "\n")
    for size in sizes:
        out.write("%sx%s " % (size, size) + " ".join("%.3f" % value.get((s, size), float("nan")) for s in series) + "\n")
device = r["device"]["name"].split(" (")[0] if r.get("device") else "no GPU"
with open(sys.argv[3] + ".n", "w") as n:
    n.write("%d\n" % (len(series) + 1))
with open(sys.argv[3], "w") as t:
    t.write("%s, %d cores (load %.1f), pond %s; GPU: %s; %s" % (r["machine"]["cpu"], r["machine"]["cores"],
            r["machine"].get("load_average", 0), r["pond"], device, r["date"]))
PY
columns=$(cat "$data.title.n")
mkdir -p "$(dirname "$out")"
gnuplot <<GP
set terminal pngcairo size 960,540 font ",10"
set output "$out"
set title "pond's water solver, exact math unless marked: M node-steps per second\n{/*0.8 $(cat "$data.title")}"
set ylabel "M node-steps / s (median)"
set xlabel "grid (nodes)"
set style data histogram
set style histogram cluster gap 1
set style fill solid 0.85 border -1
set boxwidth 0.9
set key outside right top
set grid ytics
set yrange [0:*]
# Per backend a light bar (1 thread) and a dark one (all threads); the GPU's in oranges.
colors = "#9e9ac8 #54278f #9ecae1 #08519c #a1d99b #006d2c #fc9272 #a50f15 #fdae6b #e6550d"
set xrange [-0.6:*]
plot for [c=2:$columns] "$data" using c:xtic(1) title columnheader(c) lc rgb word(colors, c - 1)
GP
echo "wrote $out"
