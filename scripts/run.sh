#!/usr/bin/env bash
# Sets up, builds and runs pond: the windowed demo when a display exists; otherwise it says so and
# renders the default scene headless to build/frame.png on lavapipe.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake --preset release > /dev/null
cmake --build --preset release -j "$(nproc)" --target pond
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  exec build/src/app/pond demo "$@"
fi
echo "run.sh: no display (DISPLAY is not set), so no window: rendering the default scene headless." >&2
build/src/app/pond render --steps 60 --frames 5 --size 1280x720 --out build/frame.png
build/src/app/pond simulate --steps 400 --out build/state.npy
echo "run.sh: wrote build/frame.png and build/state.npy; for the window, run under a display" \
     "(e.g. MALLOC_TOP_PAD_=67108864 xvfb-run -a scripts/run.sh; the variable keeps Xvfb from" \
     "halving the frame rate, see docs/demo.md)." >&2
