#!/usr/bin/env bash
# The error-budget tables of docs/CLI.md (generated blocks that tests/doc_examples.py checks):
# `--budget --summary` of data/scenes/full-budget.toml, of the scene file given, or of the
# conescan-sim options given; each source's (and all's, the sum's, the interaction's) max |error|
# and RMS of the system's roll and pitch, in Markdown.
#   scripts/budget-table.sh [SCENE.toml | OPTION...]
set -euo pipefail
cd "$(dirname "$0")/.."
sim=${CONESCAN_SIM:-build/conescan-sim}
if [ $# -eq 0 ]; then
  scene=(--config data/scenes/full-budget.toml)
elif [ $# -eq 1 ] && [[ $1 == *.toml ]]; then
  scene=(--config "$1")
else
  scene=("$@")
fi
"$sim" "${scene[@]}" --budget --summary | awk -F, '
  function absmax(lo, hi) { return (hi > -lo ? hi : -lo) + 0 }
  NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i
            print "| source | max abs roll (deg) | RMS roll (deg) | max abs pitch (deg) | RMS pitch (deg) |"
            print "|---|---|---|---|---|"; next }
  { printf "| %s | %.3g | %.3g | %.3g | %.3g |\n", $c["source"],
      absmax($c["roll_min_deg"], $c["roll_max_deg"]), $c["roll_rms_deg"] + 0,
      absmax($c["pitch_min_deg"], $c["pitch_max_deg"]), $c["pitch_rms_deg"] + 0 }'
