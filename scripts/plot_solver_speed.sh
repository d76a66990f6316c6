#!/usr/bin/env bash
# Regenerates docs/solver_speed.png: node-steps/s of the CPU solver against grid size, one line per
# backend and thread count (exact math), with the copy-bandwidth bound. Needs a release build
# (cmake --preset release && cmake --build --preset release) and gnuplot (scripts/setup.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
bench=build/bench/sim/bench_solver
data=$(mktemp)
# Two runs: Google Benchmark's CSV reporter needs the same counters in every row.
"$bench" --benchmark_filter='Sweep' --benchmark_format=csv 2>/dev/null > "$data.csv"
"$bench" --benchmark_filter='CopyBandwidth' --benchmark_format=csv 2>/dev/null | tail -n +2 >> "$data.csv"
# CSV columns: name,iterations,real_time,cpu_time,time_unit,...,label,...,counters; pick by header.
awk -F, '{ gsub(/"/, ""); $0 = $0 }
  NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
  $1 ~ /Sweep/ { split($1, p, "/"); sub("backend:", "", p[2]); sub("size:", "", p[3]); sub("threads:", "", p[4]);
                 print p[2], p[4], p[3], $col["node_steps_per_s"] }
  $1 ~ /CopyBandwidth/ { print "bound", $NF > "/dev/stderr" }' \
  "$data.csv" > "$data" 2> "$data.bound"
bound=$(awk '{print $2}' "$data.bound")
mkdir -p docs
gnuplot <<GP
set terminal pngcairo size 900,520 font ",10"
set output "docs/solver_speed.png"
set title "CPU water solver, exact math: node-steps per second"
set xlabel "grid side (nodes)"; set ylabel "M node-steps / s"
set logscale x 2; set grid; set key left top
names = "scalar sse avx2 avx512"
plot for [b=0:3] for [t in "1 $(nproc)"] sprintf("< grep '^%d %s ' $data", b, t) \
       using 3:(\$4/1e6) with linespoints \
       title sprintf("%s, %s thread%s", word(names, b+1), t, t eq "1" ? "" : "s"), \
     ${bound}/1e6 with lines dt 2 lc "gray" title "copy-bandwidth bound"
GP
echo "wrote docs/solver_speed.png"
rm -f "$data" "$data.csv" "$data.bound"
