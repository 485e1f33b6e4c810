#!/usr/bin/env bash
# Regenerates the sensor physics speed-accuracy chart with its data:
#   docs/data/sensor-physics-speed-accuracy.csv -> docs/sensor-physics-speed-accuracy.png
# from conescan-sensor-physics-speed (every method's time per head-row and worst error against the
# brute-force reference; bench/sensor_physics_speed.cpp), run on four cases along the paper's
# orbit: a 1.5 deg square on the sphere, and on WGS84's apparent horizon with the season term a
# 1.5 deg square, a 1.5 deg circle and a pencil (1 ms of lag at 1 rev/s throughout). Each case's
# full output is kept in $BUILD_DIR/sensor-physics-speed-<case>.txt. Takes some 20 minutes: the
# reference costs 10-60 s per row at h = 0.01 deg, and WGS84's table is built from the chain.
# Timings depend on the machine and its load; run it on an otherwise idle machine.
# BUILD_DIR (default build) is the CMake build directory to use; ROWS (72), REFERENCE_ROWS (4)
# and H_DEG (0.01) the benchmark's rows, reference rows and reference grid step.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
rows=${ROWS:-72}
reference_rows=${REFERENCE_ROWS:-4}
h_deg=${H_DEG:-0.01}

scripts/setup.sh gnuplot-nox
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCONESCAN_BUILD_BENCH=ON >/dev/null
cmake --build "$build" -j"$(nproc)" --target conescan-sensor-physics-speed >/dev/null

# case name, then the benchmark's options for it.
cases=(
  "sphere-square:"
  "wgs84-square:--ellipsoid --season 0.2"
  "wgs84-circle:--ellipsoid --season 0.2 --circle"
  "wgs84-pencil:--ellipsoid --season 0.2 --fov-deg 0"
)
# A line "table-day": the table's time per row over a day at 1 s with its build (the benchmark's
# "over a day at 1 s (86 400 rows) N ns/row with the build"), its error the table's.
day_row() {
  local name=$1 csv=$2 txt=$3
  awk -F, -v name="$name" -v day_ns="$(sed -n 's/.*(86 400 rows) \([0-9.]*\) ns\/row with the build.*/\1/p' "$txt")" '
    $1 == "geometric" { geometric = $2 }
    $1 == "table" { line = $0 }
    END {
      if (line == "" || day_ns == "") exit
      split(line, f, ",")
      printf "%s,table-day,%s,%s,%s,%.2f,%s,%s,%s,%s,%s\n", name, day_ns, day_ns, day_ns,
        day_ns / geometric, f[6], f[7], f[8], f[9], f[10]
    }' "$csv"
}

mkdir -p docs/data
csv=docs/data/sensor-physics-speed-accuracy.csv
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "case,method,ns_per_row,ns_min,ns_max,ratio_to_geometric,worst_error_deg,reference_rows,reference_h_deg,fast_rows,rows" >"$work/all.csv"
for entry in "${cases[@]}"; do
  name=${entry%%:*}
  # shellcheck disable=SC2086 # the options are words
  "$build"/bench/conescan-sensor-physics-speed --rows "$rows" --reference-rows "$reference_rows" \
    --h-deg "$h_deg" ${entry#*:} --chart-csv "$work/$name.csv" | tee "$build/sensor-physics-speed-$name.txt"
  tail -n +2 "$work/$name.csv" | sed "s/^/$name,/" >>"$work/all.csv"
  day_row "$name" "$work/$name.csv" "$build/sensor-physics-speed-$name.txt" >>"$work/all.csv"
done
mv "$work/all.csv" "$csv"
geometric_ns=$(awk -F, '$1 == "wgs84-square" && $2 == "geometric" { print $3 }' "$csv")
# The reference's own error at its grid step (docs/SENSOR_PHYSICS.md): ~1e-8 deg at 0.01 deg.
reference_floor=$(awk -v h="$h_deg" 'BEGIN { print (h <= 0.005 ? 3e-9 : h <= 0.01 ? 1e-8 : 1.4e-7) }')
/usr/bin/gnuplot -e "data='$csv'; output='docs/sensor-physics-speed-accuracy.png'" \
  -e "geometric_ns=$geometric_ns; reference_floor=$reference_floor" \
  bench/charts/sensor_physics_speed_accuracy.gp
echo "sensor-physics-chart: wrote $csv and docs/sensor-physics-speed-accuracy.png" >&2
