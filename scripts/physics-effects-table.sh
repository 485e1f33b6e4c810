#!/usr/bin/env bash
# The size of each sensor-physics effect (MODEL §12) beside the misalignment and the oblateness
# of docs/CLI.md's "What a scene needs" (scripts/effects-table.sh): max |roll| and |pitch| error
# of the system solution over one orbit at 10 s steps, each effect alone (sigma = 0 but for the
# misalignment row), as a Markdown table, on
#   - the paper's orbit (a = 7280 km, e = 0.1, i = 97.7 deg) with the paper's head (alpha 0,
#     beta 90, gamma 45 deg);
#   - an 800 km circular sun-synchronous orbit with the +y head alone, and with the pair of
#     pitch-axis heads (beta = +90 and -90 deg).
# The physics rows on the sphere, the limb's 50 % point 40 km above the surface and the processing
# assuming a 40 km horizon (--radiance-offset-km 40 --processing-horizon-km 40: a pencil beam
# without lag then sees exactly that horizon): a 1.5 deg square field; 1 ms of lag at 1 rev/s;
# the season term A = 0.2 at the June solstice (the Sun's declination 23.44 deg) with a fixed
# threshold (0.5 L0) and with the normalised one (1/2 of the pulse's peak).
# Generates docs/SENSOR_PHYSICS.md's effects table (tests/doc_examples.py checks it).
set -euo pipefail
cd "$(dirname "$0")/.."
sim=${CONESCAN_SIM:-build/conescan-sim}
max_errors() {  # conescan-sim options -> "roll / pitch"
  "$sim" --summary "$@" | awk -F, '
    NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
    $col["source"] == "system" {
      r = ($col["roll_max_deg"] > -$col["roll_min_deg"]) ? $col["roll_max_deg"] : -$col["roll_min_deg"]
      p = ($col["pitch_max_deg"] > -$col["pitch_min_deg"]) ? $col["pitch_max_deg"] : -$col["pitch_min_deg"]
      printf "%.3g / %.3g", r + 0, p + 0 }'
}
paper="--model scan"
sso="--model scan --a-km 7178.137 --e 0 --sun-sync"
row() {  # description, options common to all heads (the scene), head keys (each head)
  local what=$1 scene=$2 keys=$3
  local one pair_plus pair
  one=$(max_errors $paper $scene --head "beta=90,$keys")
  pair_plus=$(max_errors $sso $scene --head "beta=90,$keys")
  pair=$(max_errors $sso $scene --head "beta=90,$keys" --head "beta=-90,$keys")
  printf '| %s | `%s` | %s | %s | %s |\n' "$what" "${scene:+$scene }--head $keys" "$one" \
    "$pair_plus" "$pair"
}
echo "| effect | options (each head) | paper's orbit, one head | 800 km SSO, +y head | 800 km SSO, two heads |"
echo "|---|---|---|---|---|"
row "misalignment, phi_A = 0" "" "sigma=0.02"
row "oblateness with a 40 km horizon (modelled)" "--earth wgs84 --horizon-km 40" "sigma=0"
limb="--radiance-offset-km 40 --processing-horizon-km 40"
season="$limb --radiance-season 0.2 --sun-declination-deg 23.44"
row "field of view, 1.5 deg square" "$limb" "sigma=0,fov=1.5"
row "detector lag, 1 ms at 1 rev/s" "$limb" "sigma=0,spin-hz=1,tau-ms=1"
row "season, fixed threshold" "$season" "sigma=0,locator=fixed"
row "season, normalised threshold" "$season" "sigma=0"
