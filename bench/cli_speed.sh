#!/usr/bin/env bash
# Speed of the CLI (docs/PERFORMANCE.md): rows per second of conescan-sim streaming the paper's
# scene to /dev/null on one core, against
#   - conescan-cli-floor: the least work that produces the same columns (bench/cli_floor.cpp);
#     the target is a ratio of at least 0.6;
#   - conescan-cli-floor with conescan-sim's number formatter (src/text/shortest_double.hpp):
#     for information, how much of the ratio is the formatter;
#   - bench/numpy_paper_scene.py: a straightforward NumPy program with numpy.savetxt; the target
#     is a ratio of at least 10;
# then the formatter alone against std::to_chars on the same numbers (conescan-format-speed);
# and conescan-sim's peak memory at N and 10 N rows (it must not grow with the rows).
# Usage: bench/cli_speed.sh [STEP_S]   (default 0.01 s: ~618,000 rows of the paper's orbit)
# BUILD_DIR (default build) is the CMake build directory; RUNS (default 7) the runs per program,
# of which the median CPU time is reported (bench/cpu_time.py, to the microsecond).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
step=${1:-0.01}
runs=${RUNS:-7}

scripts/setup.sh python3-numpy time
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCONESCAN_BUILD_BENCH=ON >/dev/null
cmake --build "$build" -j"$(nproc)" --target conescan-sim conescan-cli-floor conescan-format-speed \
  >/dev/null

sim=("$build"/conescan-sim --step-s "$step")
floor=("$build"/bench/conescan-cli-floor "$step" 1)
floor_fmt=("$build"/bench/conescan-cli-floor "$step" 1 conescan)
numpy=(/usr/bin/python3 bench/numpy_paper_scene.py "$step" 1)

rows=$(("$(${sim[@]} | wc -l)" - 1))
for program in floor floor_fmt numpy; do  # the same rows, or the comparison means nothing
  declare -n cmd=$program
  other=$(("$(${cmd[@]} | wc -l)" - 1))
  [ "$other" -eq "$rows" ] || { echo "cli_speed: $program wrote $other rows, conescan-sim $rows" >&2; exit 1; }
done

# median_seconds CMD...: the median CPU time (user + system) of $runs runs, output to /dev/null,
# on one core, to the microsecond (bench/cpu_time.py).
median_seconds() { bench/cpu_time.py "$runs" "$@"; }
max_rss_kb() { /usr/bin/time -f "%M" "$@" 2>&1 >/dev/null | tail -1; }

t_sim=$(median_seconds "${sim[@]}")
t_floor=$(median_seconds "${floor[@]}")
t_floor_fmt=$(median_seconds "${floor_fmt[@]}")
t_numpy=$(median_seconds "${numpy[@]}")
rss_n=$(max_rss_kb "${sim[@]}")
rss_10n=$(max_rss_kb "$build"/conescan-sim --step-s "$(awk -v s="$step" 'BEGIN { print s / 10 }')" \
  --max-rows 100000000)

awk -v rows="$rows" -v ts="$t_sim" -v tf="$t_floor" -v tg="$t_floor_fmt" -v tn="$t_numpy" -v m1="$rss_n" \
    -v m10="$rss_10n" -v runs="$runs" 'BEGIN {
  printf "rows: %d (paper scene, one orbit); median CPU time of %d runs, one core, to /dev/null\n", rows, runs
  printf "%-28s %12s %14s\n", "program", "CPU time (s)", "rows/s"
  printf "%-28s %12.4f %14.0f\n", "conescan-sim", ts, rows / ts
  printf "%-28s %12.4f %14.0f\n", "conescan-cli-floor", tf, rows / tf
  printf "%-28s %12.4f %14.0f\n", "conescan-cli-floor conescan", tg, rows / tg
  printf "%-28s %12.4f %14.0f\n", "numpy_paper_scene.py", tn, rows / tn
  printf "conescan-sim / floor: %.2f (target >= 0.60)\n", tf / ts
  printf "conescan-sim / floor with its formatter: %.2f (for information)\n", tg / ts
  printf "conescan-sim / numpy: %.1f (target >= 10)\n", tn / ts
  printf "conescan-sim peak RSS: %d KiB at %d rows, %d KiB at %d rows\n", m1, rows, m10, 10 * rows
}'

# The formatter alone against std::to_chars, on the same numbers (bench/format_speed.cpp).
"$build"/bench/conescan-format-speed "$step"
