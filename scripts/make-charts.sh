#!/usr/bin/env bash
# Regenerates the speed-accuracy chart and the stability map, with their data:
#   docs/data/speed-accuracy.csv  -> docs/speed-accuracy.png  (conescan-speed-accuracy)
#   $BUILD_DIR/stability-map.csv  -> docs/stability-map.png   (conescan-stability-map; 4 MB,
#                                                             so not kept in docs/data)
#   docs/data/error-by-amplification.csv (the error per band of |d eta / d Phi|)
# The tables of docs/PERFORMANCE.md come from the first CSV. Takes minutes: the
# cpp_bin_float_50 reference of the scan models costs milliseconds per scene. Timings depend on
# the machine and its load; run it on an otherwise idle machine.
# BUILD_DIR (default build) is the CMake build directory to use.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}

scripts/setup.sh gnuplot-nox python3-numpy
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DCONESCAN_BUILD_BENCH=ON >/dev/null
cmake --build "$build" -j"$(nproc)" --target conescan-speed-accuracy conescan-stability-map \
  >/dev/null

mkdir -p docs/data
"$build"/bench/conescan-speed-accuracy --csv docs/data/speed-accuracy.csv \
  --bands-csv docs/data/error-by-amplification.csv
"$build"/bench/conescan-stability-map --gamma-deg 45 --sigma-deg 0.2 --phi-a-deg 180 \
  --step-deg 0.5 >"$build"/stability-map.csv

floor() {  # floor PRECISION: the floor kernel's ns per sample
  awk -F, -v p="$1" '$1 == "floor" && $2 == p { print $3 }' docs/data/speed-accuracy.csv
}
/usr/bin/gnuplot -e "data='docs/data/speed-accuracy.csv'; output='docs/speed-accuracy.png'" \
  -e "floor_float=$(floor float); floor_double=$(floor double)" \
  -e "floor_long_double=$(floor long-double)" bench/charts/speed_accuracy.gp
/usr/bin/gnuplot -e "data='$build/stability-map.csv'; output='docs/stability-map.png'" \
  -e "gamma_deg=45; sigma_deg=0.2; phi_a_deg=180; step_deg=0.5" \
  bench/charts/stability_map.gp
echo "make-charts: wrote docs/speed-accuracy.png and docs/stability-map.png" >&2
