#!/usr/bin/env bash
# Sets up, builds and runs the paper's scene: the first CSV rows and the max |roll|, |pitch|.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh --target conescan-sim
out=$(mktemp)
trap 'rm -f "$out"' EXIT
echo "paper-scene: running build/conescan-sim (the paper's scene, one orbit at 10 s steps)" >&2
build/conescan-sim > "$out"
head -n 4 "$out"
echo "..."
awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
  { r = $col["roll_err_deg"]; p = $col["pitch_err_deg"]; if (r < 0) r = -r; if (p < 0) p = -p;
    if (r > mr) mr = r; if (p > mp) mp = p; n++ }
  END { printf "paper scene: %d rows, max |roll_err| = %.6g deg, max |pitch_err| = %.6g deg (paper: < 0.02 deg)\n", n, mr, mp }' "$out"
