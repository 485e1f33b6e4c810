#!/usr/bin/env bash
# The error left after calibration per sensor-physics effect (MODEL §12), with constant biases
# only and with the physics free (docs/CALIBRATION.md, "What calibration leaves, per effect"):
# max |roll| / |pitch| error of the system solution over one orbit at 10 s steps, as a Markdown
# table, before calibration, after --apply of a fit of the crossing biases alone, and after
# --apply of a fit with the effect's physics parameter free, on
#   - the paper's ellipse (a = 7280 km, e = 0.1, i = 97.7 deg) and
#   - an 800 km circular sun-synchronous orbit,
# with the paper's head (alpha 0, beta 90, gamma 45 deg, no misalignment). Each effect alone, as
# scripts/physics-effects-table.sh simulates it: the limb's 50 % point 40 km above the surface
# and the processing assuming a 40 km horizon; 1 ms of lag at 1 rev/s; a 1.5 deg square field;
# the limb 5 km higher than the processing assumes (45 km); the season term A = 0.2 at the June
# solstice with a fixed threshold (0.5 L0).
#
# The telemetry is conescan-sim's, noise-free (one orbit at 10 s; the field's at 60 s, its fit
# taking 0.64 s per measurement in Jets); each fit weights it as 0.001 deg of noise, least
# squares without the robust loss. The fits:
#   - constant biases: the geometric scan model with a 40 km horizon (no physics), hK.bias-in and
#     hK.bias-out free;
#   - physics free: the scene's physics as the sensor's design states it (its spin, field,
#     locator; the limb at the nominal 40 km; the season term given: A known), the parameter free
#     (the lag's tau-ms from 0.5 ms, else radiance-offset-km from 40 km), with the two biases
#     on the ellipse; on the circular orbit the parameter alone, since there it and the biases
#     are one combination the data cannot separate. The corrected run's processing then assumes
#     the fitted limb height (horizon-km + radiance-offset-km: --apply removes the head's errors,
#     the processing's Earth is the user's to set). The field has no parameter of its own: its
#     column is the field modelled with the limb's height and the biases free. Nor has the
#     season term: --apply predicts through the scene's own term (the truth's, in conescan-sim),
#     so the fits that do not know it are compared by their residuals, in a second table.
# CONESCAN_SIM, CONESCAN_FIT (default build/conescan-sim, build/conescan-fit) are the programs.
set -euo pipefail
cd "$(dirname "$0")/.."
sim=${CONESCAN_SIM:-build/conescan-sim}
fit=${CONESCAN_FIT:-build/conescan-fit}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

max_errors() {  # conescan-sim options -> "roll / pitch" (deg)
  "$sim" "$@" | scripts/max-errors.sh |
    sed -E 's/.*max \|roll_err\| = ([^ ]+) deg, max \|pitch_err\| = ([^ ]+) deg.*/\1 \2/' |
    awk '{ printf "%.2g / %.2g", $1, $2 }'
}
limb_height() {  # fit JSON -> horizon-km + radiance-offset-km
  /usr/bin/python3 -c 'import json, sys
p = json.load(open(sys.argv[1]))["parameters"]
print(p["horizon-km"]["estimate"] + p["radiance-offset-km"]["estimate"])' "$1"
}

paper="--model scan"
sso="--model scan --a-km 7178.137 --e 0 --sun-sync"
# One cell group: orbit options, the truth's options and head keys, the telemetry step, the
# physics fit's scene options, head keys and --free list -> "before | biases | physics".
cells() {
  local orbit=$1 truth=$2 keys=$3 step=$4 fit_scene=$5 fit_keys=$6 free=$7
  local head="beta=90,$keys" csv="$work/telemetry.csv"
  # shellcheck disable=SC2086
  "$sim" $orbit $truth --processing-horizon-km 40 --step-s "$step" --head "$head" >"$csv"
  local fitting=(--telemetry "$csv" --step-s "$step" --loss none --json)
  # shellcheck disable=SC2086
  "$fit" $orbit "${fitting[@]}" --horizon-km 40 --head beta=90,sigma=0,noise=0.001 \
    --free h1.bias-in,h1.bias-out >"$work/biases.json"
  # shellcheck disable=SC2086
  "$fit" $orbit "${fitting[@]}" --radiance-offset-km 40 $fit_scene \
    --head "beta=90,sigma=0,noise=0.001${fit_keys:+,$fit_keys}" --free "$free" >"$work/physics.json"
  local before biases physics
  # shellcheck disable=SC2086
  before=$(max_errors $orbit $truth --processing-horizon-km 40 --head "$head")
  # shellcheck disable=SC2086
  biases=$(max_errors $orbit $truth --processing-horizon-km 40 --head "$head" \
    --apply "$work/biases.json")
  # shellcheck disable=SC2086
  physics=$(max_errors $orbit $truth --processing-horizon-km "$(limb_height "$work/physics.json")" \
    --head "$head" --apply "$work/physics.json")
  printf '%s | %s | %s' "$before" "$biases" "$physics"
}
row() {  # effect, truth options, head keys, step, physics fit's options, head keys, parameter
  local what=$1 truth=$2 keys=$3 step=$4 fit_scene=$5 fit_keys=$6 parameter=$7
  local ellipse circle
  ellipse=$(cells "$paper" "$truth" "$keys" "$step" "$fit_scene" "$fit_keys" \
    "h1.bias-in,h1.bias-out,$parameter")
  circle=$(cells "$sso" "$truth" "$keys" "$step" "$fit_scene" "$fit_keys" "$parameter")
  # shellcheck disable=SC2016  # the backticks are Markdown's
  printf '| %s | `%s --head %s` | `%s` | %s | %s |\n' "$what" "$truth" "$keys" "$parameter" \
    "$ellipse" "$circle"
}

echo "| effect | truth | physics free | ellipse: before | biases | physics | 800 km SSO: before | biases | physics |"
echo "|---|---|---|---|---|---|---|---|---|"
limb="--radiance-offset-km 40"
season="--radiance-season 0.2 --sun-declination-deg 23.44"
row "detector lag, 1 ms at 1 rev/s" "$limb" "sigma=0,spin-hz=1,tau-ms=1" 10 "" \
  "spin-hz=1,tau-ms=0.5" "h1.tau-ms"
row "limb 5 km above the assumed 40 km" "--radiance-offset-km 45" "sigma=0" 10 "" "" \
  "radiance-offset-km"
row "season term A = 0.2, fixed threshold (A known)" "$limb $season" "sigma=0,locator=fixed" 10 \
  "$season" "locator=fixed" "radiance-offset-km"
row "field of view, 1.5 deg square (telemetry at 60 s)" "$limb" "sigma=0,fov=1.5" 60 "" \
  "fov=1.5" "radiance-offset-km"

# The season term unknown to the fit: the limb's height global or drifting (one value per 600 s,
# about ten per orbit). --apply refuses a drifting fit, and predicts through the scene's own
# season term, so this is what the fits' residuals show: their RMS (deg).
rms() {  # conescan-fit options -> the residual RMS of head 1
  "$fit" "$@" --json | /usr/bin/python3 -c 'import json, sys
print("%.2g" % json.load(sys.stdin)["residual_rms_deg"]["h1"])'
}
season_rms() {  # orbit options, the global parameters freed beside the limb's height
  local orbit=$1 beside=$2 csv="$work/season.csv"
  # shellcheck disable=SC2086
  "$sim" $orbit $limb $season --processing-horizon-km 40 --head beta=90,sigma=0,locator=fixed \
    >"$csv"
  local fitting=(--telemetry "$csv" --loss none)
  local physics=(--radiance-offset-km 40 --head "beta=90,sigma=0,noise=0.001,locator=fixed")
  # shellcheck disable=SC2086
  printf '%s | %s | %s' \
    "$(rms $orbit "${fitting[@]}" --horizon-km 40 --head beta=90,sigma=0,noise=0.001 \
      --free h1.bias-in,h1.bias-out)" \
    "$(rms $orbit "${fitting[@]}" "${physics[@]}" --free "${beside}radiance-offset-km")" \
    "$(rms $orbit "${fitting[@]}" "${physics[@]}" --free "${beside}radiance-offset-km@600")"
}
echo
echo "| season term A = 0.2 unknown to the fit: residual RMS (deg) | biases | limb height | limb height drifting (600 s) |"
echo "|---|---|---|---|"
echo "| paper's ellipse (biases free beside the limb) | $(season_rms "$paper" h1.bias-in,h1.bias-out,) |"
echo "| 800 km SSO | $(season_rms "$sso" "") |"
