#!/usr/bin/env bash
# Fuzzes the scene reader and the engine: builds tests/fuzz/scene_fuzz with clang, libFuzzer,
# AddressSanitizer and UndefinedBehaviorSanitizer, and runs it for SECONDS (default 60) on a
# corpus seeded from scenes/*.toml, tests/fuzz/seeds/ and tests/fuzz/regressions/. Exits
# non-zero on a crash, a leak, a sanitizer report or a timeout; the input that did it is left in
# $FUZZ_BUILD_DIR/artifacts/ and the line to reproduce it is printed. Copied into
# tests/fuzz/regressions/, an input becomes a test (tests/engine/scene/fuzz_regressions_test.cpp).
# Usage: bash scripts/fuzz.sh [SECONDS]
# FUZZ_BUILD_DIR overrides the build directory (default: build-fuzz). Works from any directory.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

seconds="${1:-60}"
build_dir="${FUZZ_BUILD_DIR:-build-fuzz}"
jobs="$(nproc 2>/dev/null || echo 2)"

bash scripts/setup.sh fuzz
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 \
  -DMDRSIM_WERROR=ON -DMDRSIM_SANITIZE=fuzzer-no-link,address,undefined -DMDRSIM_BUILD_FUZZ=ON
cmake --build "$build_dir" -j"$jobs" --target scene_fuzz

fuzzer="$build_dir/tests/fuzz/scene_fuzz"
corpus="$build_dir/corpus"      # grows across runs in the same build directory
artifacts="$build_dir/artifacts/"
mkdir -p "$corpus" "$artifacts"
log="$build_dir/fuzz.log"
echo "fuzz: running $fuzzer for ${seconds} s (log: $log)" >&2
status=0
# -timeout: one input may take at most 20 s (the harness caps springs and steps far below);
# -rss_limit_mb: a run needs little memory (nothing is stored per spring).
ASAN_OPTIONS="detect_leaks=1:abort_on_error=1" \
UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
  "$fuzzer" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048 -max_len=8192 \
  -dict=tests/fuzz/scene.dict -artifact_prefix="$artifacts" -print_final_stats=1 \
  "$corpus" scenes tests/fuzz/seeds tests/fuzz/regressions >"$log" 2>&1 || status=$?
if [ "$status" -ne 0 ]; then
  tail -n 80 "$log" >&2
  for f in "$artifacts"*; do
    [ -e "$f" ] && echo "fuzz: found $f; reproduce with: $fuzzer $f;" \
      "keep it as a test: cp $f tests/fuzz/regressions/NAME.toml" >&2
  done
  echo "fuzz: FAILED (exit $status)" >&2
  exit "$status"
fi
grep -E '^(#[0-9]+ +DONE|Done [0-9]+ runs|stat::number_of_executed_units|stat::peak_rss_mb)' "$log" >&2 || true
echo "fuzz: no crash in ${seconds} s, corpus of $(find "$corpus" -type f | wc -l) inputs" >&2
