#!/usr/bin/env bash
# The rows of a conescan-sim CSV and its largest system errors: "N rows, max |roll_err| = X deg,
# max |pitch_err| = Y deg" over the rows whose system status is ok (the others, whose errors are
# nan, are counted: ", K rows not ok"). Reads FILE, or standard input without one. Exit 2 when
# the input is not a conescan-sim CSV.
# Usage: scripts/max-errors.sh [FILE.csv]
set -euo pipefail
awk -F, '
  NR == 1 {
    for (i = 1; i <= NF; i++) col[$i] = i
    if (!("roll_err_deg" in col) || !("pitch_err_deg" in col) || !("status" in col)) {
      print "max-errors: not a conescan-sim CSV (no roll_err_deg, pitch_err_deg, status)" > "/dev/stderr"
      failed = 1
      exit 2
    }
    next
  }
  { n++ }
  $col["status"] != "ok" { not_ok++; next }
  {
    r = $col["roll_err_deg"] + 0; p = $col["pitch_err_deg"] + 0
    if (r < 0) r = -r
    if (p < 0) p = -p
    if (r > max_roll) max_roll = r
    if (p > max_pitch) max_pitch = p
  }
  END {
    if (failed) exit 2
    if (NR == 0) { print "max-errors: empty input" > "/dev/stderr"; exit 2 }
    printf "%d rows, max |roll_err| = %.6g deg, max |pitch_err| = %.6g deg", n, max_roll, max_pitch
    if (not_ok) printf ", %d rows not ok", not_ok
    printf "\n"
  }' "${1:--}"
