# Sourced by the demo_*fps.sh scripts: their shared checks, runs and medians.
#   demo_timing_init NAME ROUNDS   checks ROUNDS, the release build's pond and Xvfb; sets $pond,
#                                  $rounds, $work (removed on exit) and stops the X servers started
#   start_x ENV                    starts an Xvfb (extra environment ENV) and sets $display to its
#                                  display (not printed: a $(...) subshell would lose its pid, and
#                                  the exit trap would leave the server running)
#   demo_ms DISPLAY SCENE [CPU]    one 200-frame 1280x720 demo run: prints its ms a frame, and
#                                  appends the CPU ms a frame its summary gives (every thread of
#                                  pond's, lavapipe's included) to the file CPU when given
#   print_median LABEL FILE [no-fps]  the median, min and max of FILE's numbers (ms), and FPS
#                                  unless the third argument is given (a CPU time is no rate)
# The X server's malloc: Xvfb reads each frame's XPutImage request (lavapipe's software present
# sends the whole 3.7 MB image through the socket: its WSI has no shared-memory path without DRI3)
# into a buffer it frees afterwards, and glibc hands that memory back to the kernel and faults it in
# again every frame. MALLOC_TOP_PAD_=67108864 ("tuned") keeps it mapped; pond itself is unchanged.

demo_timing_init() {
  script=$1
  rounds=$2
  [[ $rounds =~ ^[1-9][0-9]*$ ]] || { echo "$script: ROUNDS must be a positive integer, not '$rounds'" >&2; exit 2; }
  pond=build/src/app/pond
  [ -x "$pond" ] ||
    { echo "$script: $pond is missing: build first (cmake --preset release && cmake --build --preset release)" >&2; exit 2; }
  command -v Xvfb > /dev/null || { echo "$script: Xvfb is missing: scripts/setup.sh installs it" >&2; exit 2; }
  export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
  work=$(mktemp -d)
  x_pids=()
  trap 'kill "${x_pids[@]}" 2> /dev/null || true; rm -rf "$work"' EXIT
}

start_x() {
  local fd="$work/fd.${#x_pids[@]}"
  env $1 Xvfb -displayfd 3 -screen 0 1600x1000x24 -nolisten tcp 3> "$fd" > /dev/null 2>&1 &
  x_pids+=($!)
  for _ in $(seq 50); do [ -s "$fd" ] && break; sleep 0.1; done
  [ -s "$fd" ] || { echo "$script: Xvfb did not start" >&2; exit 1; }
  display=$(cat "$fd")
}

# Prints the ms a frame of one demo run on display $1 with scene file $2; appends its CPU ms a
# frame to file $3 when given.
demo_ms() {
  local line ms cpu
  line=$(DISPLAY=:$1 "$pond" demo --scene "$2" --frames 200 --size 1280x720 --no-vsync 2>&1 | tail -n 1)
  ms=$(grep -oE '[0-9.]+ ms/frame' <<< "$line" | grep -oE '^[0-9.]+') ||
    { echo "$script: the demo failed on $2: $line" >&2; exit 1; }
  if [ -n "${3:-}" ]; then
    cpu=$(grep -oE 'CPU [0-9.]+ ms a frame' <<< "$line" | grep -oE '[0-9.]+') ||
      { echo "$script: the demo's summary has no CPU time: $line" >&2; exit 1; }
    echo "$cpu" >> "$3"
  fi
  echo "$ms"
}

print_median() {
  sort -n "$2" | awk -v label="$1" -v fps="${3:-fps}" '{a[NR] = $1}
    END {m = NR % 2 ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2;
         rate = fps == "fps" ? sprintf(" (%5.1f FPS)", 1000 / m) : "";
         printf "  %-26s %6.2f ms%s  %.2f-%.2f\n", label, m, rate, a[1], a[NR]}'
}
