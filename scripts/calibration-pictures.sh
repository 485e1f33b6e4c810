#!/usr/bin/env bash
# The calibration's pictures in docs/ (docs/CALIBRATION.md, "Pictures"), by scripts/plot-fit.py:
#  - the README's recovery example (one day at 1 Hz, two heads, six free parameters): conescan-fit
#    --json --residuals, then per head the residuals against time and latitude
#    (docs/calibration-residuals-h1.png, -h2.png) and the correlation matrix
#    (docs/calibration-correlation.png);
#  - the seasonal horizon of scripts/calibration-season.sh (run it first: its JSON and truth in
#    docs/data/): the day-by-day history with its 1 sigma band and the truth
#    (docs/calibration-season.png).
# BUILD_DIR (default build) is the CMake build directory.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j"$(nproc)" --target conescan-sim conescan-fit >/dev/null

"$build"/conescan-sim --model scan --step-s 1 --duration-s 86400 --horizon-km 42 --seed 15 \
  --head sigma=0.05,phase=60,dgamma=0.02,noise=0.01 \
  --head beta=-90,sigma=0.03,phase=200,noise=0.01 >"$work/day.csv"
"$build"/conescan-fit --telemetry "$work/day.csv" --model scan --step-s 1 --duration-s 86400 \
  --horizon-km 40 --head sigma=0,noise=0.01 --head beta=-90,sigma=0,noise=0.01 \
  --free h1.sigma,h1.phase,h1.dgamma,h2.sigma,h2.phase,horizon-km --json \
  --residuals "$work/residuals.csv" >"$work/fit.json"
/usr/bin/python3 scripts/plot-fit.py "$work/fit.json" "$work/recovery" \
  --residuals "$work/residuals.csv" --title "the README's recovery example: one day at 1 Hz"
cp "$work/recovery/residuals-h1.png" docs/calibration-residuals-h1.png
cp "$work/recovery/residuals-h2.png" docs/calibration-residuals-h2.png
cp "$work/recovery/correlation.png" docs/calibration-correlation.png
/usr/bin/python3 scripts/plot-fit.py docs/data/calibration-season.json "$work/season" \
  --truth horizon-shift-km=docs/data/calibration-season-truth.csv:shift_km \
  --title "30 days at 1 Hz: the apparent horizon's seasonal shift, one value a day"
cp "$work/season/drift-horizon-shift-km.png" docs/calibration-season.png
echo "calibration-pictures: wrote docs/calibration-{residuals-h1,residuals-h2,correlation,season}.png" >&2
