#!/usr/bin/env bash
# Installs what is missing, builds everything with warnings as errors and runs the test suite.
# Exit code: ctest's (0 when every test passes). Works from any directory.
# BUILD_DIR overrides the build directory (default: build).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

build_dir="${BUILD_DIR:-build}"

bash scripts/setup.sh
BUILD_DIR="$build_dir" bash scripts/build.sh

status=0
ctest --test-dir "$build_dir" --output-on-failure -j2 || status=$?
exit "$status"
