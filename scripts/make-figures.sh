#!/usr/bin/env bash
# Regenerates the paper's figures in docs/ from the scene files:
#   docs/fig2a.png  <- data/scenes/paper-fig2a.toml (one head, e swept 0 to 0.1; Fig. 2(a))
#   docs/fig2b.png  <- data/scenes/paper-fig2b.toml (heads OH-1 and OH-2 at e = 0.1; Fig. 2(b))
# Builds conescan-sim into build/ first, unless CONESCAN_SIM names a binary to use.
set -euo pipefail
cd "$(dirname "$0")/.."

if [ -n "${CONESCAN_SIM:-}" ]; then
  sim=$CONESCAN_SIM
else
  scripts/setup.sh
  scripts/build.sh --target conescan-sim
  sim=build/conescan-sim
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# run SCENE CSV: the scene's CSV, or a clear failure.
run() {
  if ! "$sim" --config "$1" >"$2"; then
    echo "make-figures: $sim --config $1 failed" >&2
    exit 1
  fi
}

# A conescan-sim that does not read the whole scene file would still write a plausible CSV (the
# paper's default head, no sweep), and with it a wrong figure: check that the file's sweep and
# heads reached the output.
expect_header() {
  local csv=$1 pattern=$2 what=$3
  if ! head -n 1 "$csv" | grep -Eq "$pattern"; then
    echo "make-figures: $sim did not apply $what from the scene file (CSV header:" >&2
    echo "  $(head -n 1 "$csv" | cut -c1-100)...); does it read --config scene files?" >&2
    exit 1
  fi
}

run data/scenes/paper-fig2a.toml "$work/fig2a.csv"
expect_header "$work/fig2a.csv" '^e,t_s,' 'sweep = "e=..."'
mkdir -p docs
scripts/plot.sh "$work/fig2a.csv" docs/fig2a.png --x nu_deg \
  --title "Fig. 2(a): one head (alpha 0, beta 90, gamma 45, sigma 0.02 deg), a = 7280 km, e = 0 to 0.1"

run data/scenes/paper-fig2b.toml "$work/fig2b.csv"
expect_header "$work/fig2b.csv" '(^|,)h2_roll_err_deg(,|$)' 'the second [[head]]'
scripts/plot.sh "$work/fig2b.csv" docs/fig2b.png --x nu_deg --heads \
  --title "Fig. 2(b): heads OH-1 (beta +90 deg) and OH-2 (beta -90 deg), a = 7280 km, e = 0.1"

echo "make-figures: wrote docs/fig2a.png and docs/fig2b.png" >&2
