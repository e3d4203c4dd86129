#!/usr/bin/env bash
# The whole test suite, as CI runs it (.ci/run), in four stages:
#   1. check the layout's include rule (scripts/check_includes.sh) and the docs' relative links
#      (scripts/check_doc_links.py), build (Release, warnings as errors) and run every test with
#      ctest;
#   2. install the Python module the way docs/python.md says, offline into a fresh venv
#      (pip install -v --no-build-isolation --no-deps --no-index .), run its one-line check and
#      the console script, and
#      the module's tests with pytest (python/tests) on the installed module. (The module's
#      build is its own, in build-python-package: it needs position-independent code, which
#      costs the command 10-20 % per event, so the C++ build of stage 1 stays without it.)
#   3. build again with clang, AddressSanitizer + UndefinedBehaviorSanitizer (leak checks on)
#      and run the same C++ tests there, except those labelled `unsanitized` (the 10^7-spring
#      case, the random set's rtol 1e-6 and plain-row runs, the install tree's builds: minutes
#      under ASan for paths the other tests cover; tests/test_labels.cmake);
#   4. fuzz the scene reader and the engine for FUZZ_SECONDS (default 60, scripts/fuzz.sh) with
#      the libFuzzer target of that same build.
# `bash scripts/test.sh --quick` runs stage 1 only (no Python), and of its tests only the
# everyday subset (ctest -L quick: every test under about 2 s, under two minutes on 2 cores;
# tests/test_labels.cmake lists the slow ones). Installs what is missing first.
# Exit code: 0 when every stage passes. Works from any directory.
# BUILD_DIR and FUZZ_BUILD_DIR move the two build directories (default: build, build-fuzz);
# stage 2 builds in build-python-package (setup.py; MDRSIM_PYTHON_BUILD_DIR moves it).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

quick=0
case "${1:-}" in
  "") ;;
  --quick) quick=1 ;;
  *) echo "usage: bash scripts/test.sh [--quick]" >&2; exit 2 ;;
esac
build_dir="${BUILD_DIR:-build}"
sanitize_dir="${FUZZ_BUILD_DIR:-build-fuzz}"
jobs="$(nproc 2>/dev/null || echo 2)"
logs="$(mktemp -d)"
trap 'rm -rf "$logs"' EXIT
stage() { echo "=== test.sh: $* ($(date -u +%H:%M:%S))" >&2; }
# ctest's closing line "N% tests passed, F tests failed out of T", added over the stages; ctest
# counts a skipped test (GTEST_SKIP) as passed and lists it as "(Skipped)": told apart here.
# pytest's closing line ("40 passed, 2 skipped in 1.2s") is added in as it stands.
totals() {
  local skipped
  skipped="$(cat "$logs"/ctest*.log | grep -c '(Skipped)$' || true)"
  {
    cat "$logs"/ctest*.log | sed -n 's/.* \([0-9][0-9]*\) tests failed out of \([0-9][0-9]*\).*/ctest \1 \2/p'
    if [ -f "$logs/pytest.log" ]; then tail -n 1 "$logs/pytest.log" | sed 's/^/pytest /'; fi
  } | awk -v s="$skipped" '
    $1 == "ctest" {f += $2; t += $3 - $2}
    $1 == "pytest" {for (i = 3; i <= NF; i++) {w = $i; sub(/,$/, "", w)
      if (w == "passed") t += $(i - 1); if (w == "failed" || w == "errors" || w == "error") f += $(i - 1)
      if (w == "skipped") {s += $(i - 1); t += $(i - 1)}}}
    END {printf "%d passed, %d failed, %d skipped\n", t - s, f, s}'
}

if [ "$quick" -eq 1 ]; then bash scripts/setup.sh; else bash scripts/setup.sh fuzz; fi

stage "1/4 build and test ($build_dir)"
bash scripts/check_includes.sh
/usr/bin/python3 scripts/check_doc_links.py
# Without the Python module (an earlier configuration may have cached it on): see stage 2.
cmake -S . -B "$build_dir" -DMDRSIM_PYTHON=OFF >/dev/null
BUILD_DIR="$build_dir" bash scripts/build.sh
labels=()
if [ "$quick" -eq 1 ]; then labels=(-L quick); fi
ctest --test-dir "$build_dir" --output-on-failure -j"$jobs" "${labels[@]}" | tee "$logs/ctest1.log"
if [ "$quick" -eq 1 ]; then
  echo "tests: $(totals)"
  exit 0
fi

stage "2/4 install the Python module offline into a fresh venv (docs/python.md), pytest"
venv="$logs/venv"
/usr/bin/python3 -m venv --system-site-packages "$venv"
# -v: setup.py's step lines and CMake's progress as the build goes (pip is silent without it).
"$venv/bin/pip" install -v --no-build-isolation --no-deps --no-index .
"$venv/bin/python" -c "import mdrsim; print(mdrsim.__file__)" | grep -q "^$venv/lib/"
"$venv/bin/mdrsim" --version  # the console script, installed with the package
"$venv/bin/python" -c "import mdrsim; print(mdrsim.run(mdrsim.Scene.from_file('scenes/fig2_fixed_load.toml')).critical)"
# The tests on the installed module, compared with the mdrsim command of stage 1.
MDRSIM_CLI="$build_dir/apps/mdrsim" \
  "$venv/bin/python" -m pytest -q -p no:cacheprovider python/tests | tee "$logs/pytest.log"

stage "3/4 build and test under AddressSanitizer and UndefinedBehaviorSanitizer ($sanitize_dir)"
# The configuration of scripts/fuzz.sh, so that stage 4 reuses this build: the coverage
# instrumentation it adds (fuzzer-no-link) does not change what the tests check.
cmake -S . -B "$sanitize_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 \
  -DMDRSIM_WERROR=ON -DMDRSIM_SANITIZE=fuzzer-no-link,address,undefined -DMDRSIM_BUILD_FUZZ=ON
cmake --build "$sanitize_dir" -j"$jobs"
# Any report aborts the test that caused it (-fno-sanitize-recover=all, abort_on_error); the
# tests run the mdrsim binary too, which inherits these options. Left out here (run in stage 1):
# the cases labelled `unsanitized` (tests/test_labels.cmake), which only repeat covered paths
# on huge rows or many scenes, 10 to 20 times slower under the sanitizers (10^7 springs; the
# random set at rtol 1e-6 and on the plain rows, up to 2^25 springs; every example scene run
# twice for byte-identical JSON: 94 s alone), and the install tree's builds; with them the CI
# would pass its 30 minutes on 2 cores.
ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=1:strict_string_checks=1" \
UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
  ctest --test-dir "$sanitize_dir" --output-on-failure -j"$jobs" -LE unsanitized |
  tee "$logs/ctest3.log"

stage "4/4 fuzz for ${FUZZ_SECONDS:-60} s"
FUZZ_BUILD_DIR="$sanitize_dir" bash scripts/fuzz.sh "${FUZZ_SECONDS:-60}"
stage "all stages passed"
echo "tests: $(totals)"  # normal and sanitizer builds together
