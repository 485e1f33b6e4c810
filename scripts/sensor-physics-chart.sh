#!/usr/bin/env bash
# Regenerates the sensor physics speed-accuracy chart with its data:
#   docs/data/sensor-physics-speed-accuracy.csv -> docs/sensor-physics-speed-accuracy.png
# from conescan-sensor-physics-speed (every method's time per head-row and worst error against the
# brute-force reference; bench/sensor_physics_speed.cpp). The table of docs/SENSOR_PHYSICS.md
# ("The fast method") comes from the same run, whose full output is kept in
# $BUILD_DIR/sensor-physics-speed.txt. Takes minutes: the reference costs 10-60 s per row at
# h = 0.01 deg. Timings depend on the machine and its load; run it on an otherwise idle machine.
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

mkdir -p docs/data
csv=docs/data/sensor-physics-speed-accuracy.csv
"$build"/bench/conescan-sensor-physics-speed --rows "$rows" --reference-rows "$reference_rows" \
  --h-deg "$h_deg" --chart-csv "$csv" | tee "$build"/sensor-physics-speed.txt
geometric_ns=$(awk -F, '$1 == "geometric" { print $2 }' "$csv")
# The reference's own error at its grid step (docs/SENSOR_PHYSICS.md): ~1e-8 deg at 0.01 deg.
reference_floor=$(awk -v h="$h_deg" 'BEGIN { print (h <= 0.005 ? 3e-9 : h <= 0.01 ? 1e-8 : 1.4e-7) }')
/usr/bin/gnuplot -e "data='$csv'; output='docs/sensor-physics-speed-accuracy.png'" \
  -e "geometric_ns=$geometric_ns; reference_floor=$reference_floor" \
  bench/charts/sensor_physics_speed_accuracy.gp
echo "sensor-physics-chart: wrote $csv and docs/sensor-physics-speed-accuracy.png" >&2
