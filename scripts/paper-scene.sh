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
echo "paper scene: $(scripts/max-errors.sh "$out") (paper: < 0.02 deg)"
