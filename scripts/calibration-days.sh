#!/usr/bin/env bash
# How each parameter's 1 sigma shrinks with days of data (docs/CALIBRATION.md's guide):
# conescan-fit --predict (the Fisher information of the planned scene, no data) for the recovery
# scene of that guide at 1 s telemetry, over 1/8 to 8 days.
#   docs/data/calibration-days.csv -> docs/calibration-days.png (bench/charts/calibration_days.gp)
# BUILD_DIR (default build) is the CMake build directory to use. With --csv: only the CSV, on
# standard output, from the programs already built (ctest docs.data_files compares it with the
# committed file: docs/data/regenerated.txt).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}

free=h1.sigma,h1.phase,h1.dgamma,h2.sigma,h2.phase,horizon-km
csv() {
  echo "days,${free}"
  for days in 0.125 0.25 0.5 1 2 4 8; do
    duration=$(/usr/bin/python3 -c "print(int($days * 86400))")
    "$build"/conescan-fit --predict --json --model scan --step-s 1 --duration-s "$duration" \
      --horizon-km 42 --head sigma=0.05,phase=60,dgamma=0.02,noise=0.01 \
      --head beta=-90,sigma=0.03,phase=200,noise=0.01 --free "$free" |
      /usr/bin/python3 -c "
import json, sys
design = json.load(sys.stdin)
names = '$free'.split(',')
print(','.join(['$days'] + [repr(design['parameters'][n]['sigma']) for n in names]))"
  done
}
if [ "${1:-}" = --csv ]; then
  csv
  exit
fi

scripts/setup.sh gnuplot-nox
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j"$(nproc)" --target conescan-fit >/dev/null
mkdir -p docs/data
csv >docs/data/calibration-days.csv
/usr/bin/gnuplot -e "data='docs/data/calibration-days.csv'; output='docs/calibration-days.png'" \
  bench/charts/calibration_days.gp
echo "calibration-days: wrote docs/data/calibration-days.csv and docs/calibration-days.png" >&2
