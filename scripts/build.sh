#!/usr/bin/env bash
# Configures and builds mdrsim in $BUILD_DIR (default: build) with the flags CI uses:
# Release, warnings as errors. Extra arguments are build targets (default: all), e.g.
#   bash scripts/build.sh mdrsim      # just the command-line program
# Works from any directory; the build directory is relative to the repository root.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

build_dir="${BUILD_DIR:-build}"
jobs="$(nproc 2>/dev/null || echo 2)"

# bench/ is built too, so that CI compiles it with warnings as errors.
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DMDRSIM_WERROR=ON -DMDRSIM_BUILD_BENCH=ON
if [ $# -eq 0 ]; then
  cmake --build "$build_dir" -j"$jobs"
else
  for target in "$@"; do
    cmake --build "$build_dir" -j"$jobs" --target "$target"
  done
fi
