#!/usr/bin/env bash
# A seasonal horizon recovered from a month of telemetry (docs/CALIBRATION.md, "Parameters that
# drift"). conescan-sim simulates 30 days at 1 Hz from 2025-03-06 (the March equinox in the
# middle) of the README's two misaligned heads on the WGS84 apparent horizon of the CO2 band
# (--horizon-preset co2-15um: 40 km, -13 km at the poles, a centre shifted north by
# 11.5 km sin(Sun's declination) with each row's own declination); conescan-fit fits it with the
# Sun held at a declination of 90 deg, so that horizon-shift-km is the centre's shift itself, and
# frees it per day (horizon-shift-km@86400) beside the global misalignments, horizon height and
# pole term. The truth of each day is the mean of 11.5 sin(declination) over its rows, the
# declination ERFA's as the rows had it (bench/season_truth.cpp; --date's is the Almanac's
# low-precision one, 0.002 deg away).
#   docs/data/calibration-season.json (the fit), docs/data/calibration-season-truth.csv;
#   scripts/calibration-pictures.sh draws them (docs/calibration-season.png).
# BUILD_DIR (default build) is the CMake build directory; STEP_S (default 1) the telemetry step;
# WORK_DIR (default a temporary directory) holds the month's CSV (0.7 GB at 1 Hz).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
step=${STEP_S:-1}
work=${WORK_DIR:-$(mktemp -d)}

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j"$(nproc)" --target conescan-sim conescan-fit conescan-season-truth \
  >/dev/null

epoch=2025-03-06T00:00:00
days=30
duration=$((days * 86400 - step))
scene=(--model scan --earth wgs84 --epoch "$epoch" --step-s "$step" --duration-s "$duration")
"$build"/conescan-sim "${scene[@]}" --horizon-preset co2-15um --seed 25 \
  --head sigma=0.05,phase=60,noise=0.01 --head beta=-90,sigma=0.03,phase=200,noise=0.01 \
  >"$work/month.csv"
fit=("${scene[@]}" --telemetry "$work/month.csv" --horizon-km 40 --horizon-pole-km -13
  --sun-declination-deg 90 --head sigma=0,noise=0.01 --head beta=-90,sigma=0,noise=0.01
  --free h1.sigma,h1.phase,h2.sigma,h2.phase,horizon-km,horizon-pole-km,horizon-shift-km@86400)
mkdir -p docs/data
/usr/bin/time -v "$build"/conescan-fit "${fit[@]}" --json >docs/data/calibration-season.json \
  2>"$work/time.txt"
grep -E "Maximum resident|Elapsed|User time" "$work/time.txt" >&2
"$build"/bench/conescan-season-truth "$epoch" "$days" 86400 "$step" 11.5 \
  >docs/data/calibration-season-truth.csv
[[ -z ${WORK_DIR:-} ]] && rm -rf "$work"
echo "calibration-season: wrote docs/data/calibration-season.json and -truth.csv" >&2
