#!/usr/bin/env bash
# Sets up, builds and runs pond. The windowed demo is not in this version yet, so this runs the
# default scene headless: 400 steps of the paper's 50 x 50 pond with an island and a splash, writes
# the state to build/state.npy and prints a summary.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake --preset release > /dev/null
cmake --build --preset release -j "$(nproc)" --target pond
build/src/app/pond simulate --steps 400 --out build/state.npy
