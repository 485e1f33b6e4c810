#!/usr/bin/env bash
# The size of each effect on the paper's orbit (a = 7280 km, e = 0.1, i = 97.7 deg, one orbit,
# 10 s steps, the paper's head alpha = 0, beta = 90, gamma = 45 deg): max |roll| and |pitch| error
# of the system solution, as a Markdown table. Generates docs/CLI.md's "What a scene needs" (tests/doc_examples.py checks it).
set -euo pipefail
cd "$(dirname "$0")/.."
sim=${CONESCAN_SIM:-build/conescan-sim}
row() {  # description, then conescan-sim options
  local what=$1
  shift
  "$sim" --summary "$@" | awk -F, -v what="$what" -v opts="$*" '
    NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
    $col["source"] == "system" {
      r = ($col["roll_max_deg"] > -$col["roll_min_deg"]) ? $col["roll_max_deg"] : -$col["roll_min_deg"]
      p = ($col["pitch_max_deg"] > -$col["pitch_min_deg"]) ? $col["pitch_max_deg"] : -$col["pitch_min_deg"]
      printf "| %s | `%s` | %.3g | %.3g |\n", what, opts, r, p }'
}
echo "| effect | conescan-sim options | max abs roll error (deg) | max abs pitch error (deg) |"
echo "|---|---|---|---|"
row "misalignment, paper's bias model" --model bias
row "misalignment, paper's bias model, phi_A = 90 deg" --model bias --head phase=90
row "misalignment, exact scan model, phi_A = 0" --model scan
row "misalignment, exact scan model, phi_A = 90 deg" --model scan --head phase=90
row "misalignment, exact scan model, phi_A = 180 deg" --model scan --head phase=180
row "oblateness alone (WGS84 truth, equatorial sphere assumed)" --earth wgs84 --model scan --head sigma=0
row "oblateness alone, local radius assumed" --earth wgs84 --model scan --head sigma=0 --processing-radius local
row "40 km CO2 horizon not modelled (sphere assumed at the surface)" --model scan --head sigma=0 --horizon-km 40 --processing-radius 6338.137
row "oblateness with a 40 km horizon (modelled)" --earth wgs84 --model scan --head sigma=0 --horizon-km 40
row "all: WGS84, 40 km horizon, misalignment phi_A = 0" --earth wgs84 --model scan --horizon-km 40
