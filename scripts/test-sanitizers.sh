#!/usr/bin/env bash
# Builds the whole project with AddressSanitizer + UndefinedBehaviorSanitizer (the asan-ubsan
# preset of CMakePresets.json: g++, -O1, -fno-sanitize-recover=all, into build-asan/) and runs
# the whole test suite under it. Any sanitizer report fails the test that triggered it.
# Arguments are passed to ctest (e.g. -R robustness). Meant for CI, after scripts/test.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
jobs=$(nproc)
[ "$jobs" -gt 2 ] && jobs=2  # the sanitizer build needs ~1 GB per compiler process
log=$(mktemp)
trap 'rm -f "$log"' EXIT
launcher=()
# ccache, where the machine has it: a rebuild of unchanged sources takes seconds.
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
echo "test-sanitizers: building with AddressSanitizer + UndefinedBehaviorSanitizer into" \
  "build-asan/ (a first build takes 10 to 20 minutes on 2 cores; log: $log)" >&2
if ! { cmake --preset asan-ubsan "${launcher[@]}" && cmake --build --preset asan-ubsan -j"$jobs"; } >"$log" 2>&1; then
  tail -n 80 "$log" >&2
  echo "test-sanitizers: the asan-ubsan build failed" >&2
  exit 1
fi
# The preset's test environment sets ASAN_OPTIONS / UBSAN_OPTIONS (leaks detected, every finding
# fatal, with a stack trace); conescan-sim run by the CLI tests inherits them.
echo "test-sanitizers: running the suite under the sanitizers (10 to 20 minutes)" >&2
ctest --preset asan-ubsan -j"$jobs" "$@"
