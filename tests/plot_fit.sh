#!/bin/sh
# scripts/plot-fit.py on a small fit with a drifting horizon (ctest calibration.plot_fit): every
# picture is written. Skipped (77) without Debian's python3-matplotlib.
# Usage: plot_fit.sh CONESCAN_SIM CONESCAN_FIT SOURCE_DIR
set -eu
sim=$1
fit=$2
source=$3
/usr/bin/python3 -c "import matplotlib, numpy" 2>/dev/null || exit 77
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
scene="--model scan --step-s 60 --orbits 1"
"$sim" $scene --seed 3 --head sigma=0.05,phase=60,noise=0.01 \
  --head beta=-90,sigma=0.03,phase=200,noise=0.01 >"$work/telemetry.csv"
"$fit" --telemetry "$work/telemetry.csv" $scene --head noise=0.01 --head beta=-90,noise=0.01 \
  --free h1.sigma,h1.phase,h2.sigma,h2.phase,horizon-km@3000 --json \
  --residuals "$work/residuals.csv" >"$work/fit.json"
/usr/bin/python3 "$source/scripts/plot-fit.py" "$work/fit.json" "$work/out" \
  --residuals "$work/residuals.csv" >"$work/written.txt"
for picture in correlation drift-horizon-km residuals-h1 residuals-h2; do
  test -s "$work/out/$picture.png" || { echo "plot-fit: no $picture.png" >&2; exit 1; }
done
