#!/usr/bin/env bash
# Builds the libFuzzer targets (the fuzz preset: clang, ASan + UBSan, into build-fuzz/) and fuzzes
# each for FUZZ_SECONDS (default 60), one after the other under nice -n 19 (a shared machine),
# starting from the seed corpus of tests/fuzz/corpus/<target>. The growing corpus and any
# crashing input stay under build-fuzz/fuzz-work/<target>/. Prints one line per target: seconds, executions, corpus size,
# and the outcome; exits 1 when a target found a fault (its input and message are shown).
#   scripts/fuzz.sh                  # all targets, 60 s each
#   FUZZ_SECONDS=600 scripts/fuzz.sh core
# A finding: reproduce with build-fuzz/tests/fuzz/fuzz_<target> <input>, fix it, copy the input
# to tests/fuzz/corpus/<target>/regress-<what> (tests/apps/test_robustness.cpp replays the corpora of
# core and head_spec) and add a regression test to tests/apps/test_robustness.cpp.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh clang libclang-rt-14-dev
seconds=${FUZZ_SECONDS:-60}
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(core head_spec options scene_file shortest_double tle omm oem
  aem attitude_csv telemetry fit_json summary_state)

log=$(mktemp)
trap 'rm -f "$log"' EXIT
if ! { cmake --preset fuzz && cmake --build --preset fuzz; } >"$log" 2>&1; then
  tail -n 80 "$log" >&2
  echo "fuzz: the fuzz build failed" >&2
  exit 1
fi

status=0
printf '%-14s %8s %12s %8s  %s\n' target seconds executions corpus outcome
for t in "${targets[@]}"; do
  bin=build-fuzz/tests/fuzz/fuzz_$t
  work=build-fuzz/fuzz-work/$t
  mkdir -p "$work/corpus" "$work/artifacts"
  dict=()
  [ -f "tests/fuzz/$t.dict" ] && dict=(-dict="tests/fuzz/$t.dict")
  # -timeout: a single input running 10 s is a hang (an unbounded loop) and counts as a finding.
  set +e
  nice -n 19 "$bin" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$work/artifacts/" "${dict[@]}" "$work/corpus" "tests/fuzz/corpus/$t" \
    >"$work/last.log" 2>&1
  rc=$?
  set -e
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/last.log" | tail -n 1)
  corpus=$(find "$work/corpus" -type f | wc -l)
  if [ $rc -eq 0 ]; then
    outcome=clean
  else
    outcome="FAULT (exit $rc): $(grep -m1 -E 'invariant broken|ERROR: |runtime error' "$work/last.log" || true)"
    status=1
  fi
  printf '%-14s %8s %12s %8s  %s\n' "$t" "$seconds" "${execs:-?}" "$corpus" "$outcome"
  if [ $rc -ne 0 ]; then
    grep -E 'Test unit written to' "$work/last.log" >&2 || true
    echo "fuzz: whole log: $work/last.log" >&2
  fi
done
exit $status
