#!/usr/bin/env bash
# Tries every fault of docs/RELIABILITY.md on conescan-sim and prints what it did, as the
# Markdown table of that page (also written to build-release/reliability-table.md):
#   bad inputs by kind, the former validation gaps, a full device (/dev/full), a full disk (a
#   1 MiB tmpfs, when run as root), a file-size limit, appending to a file, a reader that closes
#   early (with SIGPIPE default and ignored), the fuzz targets (scripts/fuzz.sh), the test suite
#   under ASan + UBSan (scripts/test-sanitizers.sh), and a 10^8-row run (peak RSS, and its last
#   row against an independent computation and against a one-row run at the same epoch).
# Not part of CI: the 10^8-row run alone takes a few minutes.
#   ROWS=100000000 FUZZ_SECONDS=60 scripts/reliability.sh
#   SKIP_FUZZ=1 SKIP_SANITIZERS=1 ROWS=1000000 scripts/reliability.sh   # a quick look
set -euo pipefail
cd "$(dirname "$0")/.."
rows=${ROWS:-100000000}
scripts/setup.sh time python3
{ cmake --preset release && cmake --build --preset release --target conescan-sim; } >/dev/null
sim=$PWD/build-release/conescan-sim
repo=$PWD
work=$(mktemp -d)
cleanup() {
  if mountpoint -q "$work/tmpfs" 2>/dev/null; then umount "$work/tmpfs" || true; fi
  rm -rf "$work"
}
trap cleanup EXIT
table=build-release/reliability-table.md
: >"$table"
row() { printf '| %s | %s | %s |\n' "$1" "$2" "$3" | tee -a "$table"; }
# The first line of stderr, as a table cell.
first_line() { head -n 1 "$1" | cut -c1-150 | sed 's/|/\\|/g'; }

echo "| fault | command | what conescan-sim did |" | tee -a "$table"
echo "|---|---|---|" | tee -a "$table"

# --- Bad inputs: exit 2, a message naming the option, no CSV ----------------------------------
bad_inputs=(
  "not a number|--e abc"
  "empty head|--head ''"
  "not key=value|--head alpha"
  "unknown head key|--head delta=1"
  "head key twice|--head alpha=1,alpha=2"
  "unknown option|--bogus"
  "option given twice|--e 0.1 --e 0.2"
  "unknown word|--earth moon"
  "unknown word|--processing-radius huge"
  "NaN|--e nan"
  "infinity|--a-km inf"
  "overflow to infinity|--e 1e999"
  "NaN in a head|--head alpha=nan"
  "out of range|--e 1"
  "out of range|--e -1e-300"
  "out of range|--i-deg 180.0000001"
  "out of range|--step-s 0"
  "out of range|--pitch-deg 90.5"
  "out of range (cone)|--head gamma=90"
  "out of range (mounting)|--head alpha=-90"
  "out of range (misalignment)|--head gamma=10,sigma=10"
  "perigee below the surface|--a-km 6000"
  "model on the wrong Earth|--earth wgs84 --model bias"
  "too many rows|--step-s 1e-9"
  "missing scene file|--config /nonexistent/scene"
  "directory as scene file|--config /"
  "not a text scene file|--config /dev/zero"
  # Former validation gaps (fuzzing): they passed validation but could not be simulated.
  "empty value (CLI11 read it as 0)|--e '' --duration-s 0"
  "tiny a: GM / a^3 overflows|--a-km 1e-300 --radius-km 1e-310 --duration-s 0"
  "huge a: a in m overflows|--a-km 1e306 --duration-s 0"
  "huge horizon: the norm of r overflows|--horizon-km 1e200 --a-km 3e200 --duration-s 0"
  "processing sphere encloses the orbit|--radius-km 1000 --a-km 2000 --e 0 --processing-radius equatorial --duration-s 0"
  "processing radius underflows|--processing-radius 5e-324 --duration-s 0"
  # accepted, misread or blamed on another option before.
  "a count with a sign (was accepted)|--max-rows -1"
  "a count with a leading zero (was read as octal 8)|--seed 010"
  "a count in hex (was accepted)|--max-rows 0x10"
  "a negative run count (blamed --max-rows)|--runs -1"
  "a count with an exponent (RELIABILITY.md used it)|--max-rows 1e9"
  "a hex float (written by --print-config, refused by the file reader)|--e 0x1p-4"
  "head keys as separate words (made three heads)|--head alpha=3 gamma=30 sigma=0.05"
  "a denormal telemetry step (rows of invalid)|--head lsb=1e-320 --duration-s 0"
  "the satellite inside the horizon's pole (rows of invalid)|--earth wgs84 --model scan --horizon-pole-km 1000 --duration-s 0"
  "the satellite inside the shifted horizon (rows of invalid)|--earth wgs84 --model scan --horizon-shift-km 1000 --sun-declination-deg 90 --duration-s 0"
  "a sweep of an overridden option (identical rows)|--sweep orbits=0:1:0.5 --duration-s 600"
  "a sweep of an overridden option (identical rows)|--sweep i-deg=0:90:90 --sun-sync"
  "a sweep that cannot advance (an endless loop)|--sweep roll-deg=1e16:1.00000000000001e16:1 --duration-s 0"
  "a sweep of 10^7 values (2.9 GB, then bad_alloc)|--sweep e=0:0.1:1e-8 --duration-s 0"
  "a preset without wgs84 (blamed --horizon-pole-km)|--horizon-preset co2-15um"
  "gamma below the default sigma (blamed sigma)|--head gamma=1e-300"
  "an empty scene-file name (ignored)|--config ''"
  "endless [[head]] tables on stdin (grew to GBs)|--config /dev/stdin < <(yes '[[head]]')"
  "endless head lines on stdin (grew to GBs)|--config /dev/stdin < <(yes 'head = \"alpha=1\"')"
)
for entry in "${bad_inputs[@]}"; do
  kind=${entry%%|*}
  args=${entry#*|}
  set +e
  eval "/usr/bin/time -f %M -o \"$work/rss\" \"$sim\" $args" >"$work/out" 2>"$work/err"
  rc=$?
  set -e
  out_bytes=$(wc -c <"$work/out")
  verdict="exit $rc, $out_bytes bytes of CSV, peak RSS $(tail -n 1 "$work/rss") KiB: $(first_line "$work/err")"
  [ $rc -eq 2 ] && [ "$out_bytes" -eq 0 ] || verdict="**UNEXPECTED** $verdict"
  row "bad input: $kind" "\`$args\`" "$verdict"
done

# --- Regressions: commands that failed or printed wrong numbers, now right -----------------------
# Each line: what was wrong | arguments | a check (shell, in $work, with $sim) that prints what
# conescan-sim did and fails if it is wrong.
right_answers=(
  "budget of a 1000 km sphere (aborted, exit 134)|--radius-km 1000 --a-km 3000 --e 0 --duration-s 0 --budget|test \$rc -eq 0 && echo \"exit 0, \$(wc -l <out) lines\""
  "a sweep whose STEP cannot advance FROM (never ended, 3.6 GB)|--sweep roll-deg=1e63:1e63:1 --duration-s 0|test \$rc -eq 0 && echo \"exit 0, \$((\$(wc -l <out) - 1)) row (TO = FROM: one value)\""
  "the seed column of 2^53 + 1 (printed 2^53)|--seed 9007199254740993 --head noise=0.01 --duration-s 0|test \"\$(sed -n 2p out | cut -d, -f1)\" = 9007199254740993 && echo \"seed column \$(sed -n 2p out | cut -d, -f1)\""
  "a roll of 1e20 deg (roll_err -100.35 deg, status ok)|--roll-deg 1e20 --model scan --duration-s 0|\"\$sim\" --roll-deg -80 --model scan --duration-s 0 | cmp -s - out && echo 'the same CSV as --roll-deg -80 (1e20 mod 360)'"
  "a value just above a midpoint (7100.1 on the command line only)|--a-km 7100.100000000000818545231595635414123535156250001 --print-config|grep -q '^a-km = 7100.100000000001\$' out && echo 'a-km = 7100.100000000001 (correctly rounded), as in files, sweeps and heads'"
  "a phase with an LSB that does not divide 360 deg (off the grid)|--model scan --duration-s 0 --pitch-deg -8 --roll-deg -0.1 --head alpha=85,beta=0,gamma=75,sigma=1,phase=90,lsb=0.007|p=\$(sed -n 2p out | cut -d, -f8); /usr/bin/python3 -c \"import sys; p = float('\$p'); k = p / 0.007; sys.exit(abs(k - round(k)) > 1e-6)\" && echo \"h1_phase_deg \$p = \$(/usr/bin/python3 -c \"print(round(\$p / 0.007))\") x 0.007\""
  "the command line over the file (refused: orbits excludes duration-s)|--config \$repo/data/scenes/full-budget.toml --duration-s 60|test \$rc -eq 0 && echo \"exit 0, \$((\$(wc -l <out) - 1)) rows (60 s at 30 s)\""
  "--trace with --budget (ignored)|--budget --trace --duration-s 0|grep -c '^trace: source=' err | sed 's/\$/ trace lines, one per source and head/'"
  "--print-config to a full device (exit 0)|--print-config >/dev/full|test \$rc -eq 1 && head -n 1 err"
  "--help to a full device (exit 0)|--help >/dev/full|test \$rc -eq 1 && head -n 1 err"
)
for entry in "${right_answers[@]}"; do
  kind=${entry%%|*}
  rest=${entry#*|}
  args=${rest%%|*}
  check=${rest#*|}
  set +e
  (cd "$work" && eval "\"$sim\" $args" >out 2>err)
  rc=$?
  verdict=$(cd "$work" && rc=$rc sim=$sim eval "$check" 2>&1)
  ok=$?
  set -e
  [ $ok -eq 0 ] || verdict="**WRONG** exit $rc: $verdict"
  row "regression: $kind" "\`$args\`" "$verdict"
done

# --- Output faults -------------------------------------------------------------------------------
# Every line of a CSV has the header's field count and the file ends with a newline.
whole_rows() {
  awk -F, 'NR == 1 { n = NF } NF != n { bad++ } END { printf "%d lines, %d not whole", NR, bad }' "$1"
  [ -s "$1" ] && [ "$(tail -c 1 "$1" | od -An -c | tr -d ' ')" = '\n' ] && printf ', ends with a newline' || printf ', **does not end with a newline**'
}

set +e
"$sim" >/dev/full 2>"$work/err"
rc=$?
set -e
row "full device" "\`conescan-sim > /dev/full\`" "exit $rc: $(first_line "$work/err")"

if [ "$(id -u)" -eq 0 ] && mkdir -p "$work/tmpfs" && mount -t tmpfs -o size=1m tmpfs "$work/tmpfs" 2>/dev/null; then
  set +e
  "$sim" --orbits 10 >"$work/tmpfs/out.csv" 2>"$work/err"
  rc=$?
  set -e
  row "full disk (1 MiB tmpfs)" "\`conescan-sim --orbits 10 > full/out.csv\`" \
    "exit $rc: $(first_line "$work/err"); file $(stat -c %s "$work/tmpfs/out.csv") B, $(whole_rows "$work/tmpfs/out.csv")"
  rm -f "$work/tmpfs/out.csv"
  printf 'earlier contents\n' >"$work/tmpfs/app.csv"
  set +e
  "$sim" --orbits 10 >>"$work/tmpfs/app.csv" 2>"$work/err"
  rc=$?
  set -e
  kept=$(head -n 1 "$work/tmpfs/app.csv")
  tail -n +2 "$work/tmpfs/app.csv" >"$work/appended.csv"
  row "full disk, appending" "\`conescan-sim --orbits 10 >> full/app.csv\`" \
    "exit $rc: $(first_line "$work/err"); first line kept: \`$kept\`; appended part $(whole_rows "$work/appended.csv")"
  umount "$work/tmpfs"
else
  row "full disk (1 MiB tmpfs)" "needs root to mount" "skipped"
fi

set +e
(ulimit -f 200 && exec "$sim" --orbits 20 >"$work/limited.csv" 2>"$work/err")
rc=$?
set -e
row "file-size limit" "\`(ulimit -f 200; conescan-sim --orbits 20 > f.csv)\`" \
  "exit $rc: $(first_line "$work/err"); file $(stat -c %s "$work/limited.csv") B, $(whole_rows "$work/limited.csv")"

for sigpipe in default ignored; do
  start=$(date +%s.%N)
  set +e
  if [ $sigpipe = default ]; then
    "$sim" --orbits 100000 --max-rows 1000000000 2>"$work/err" | head -c 4096 >/dev/null
  else
    (trap '' PIPE && exec "$sim" --orbits 100000 --max-rows 1000000000 2>"$work/err") | head -c 4096 >/dev/null
  fi
  rc=${PIPESTATUS[0]}
  set -e
  took=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.3f", e - s }')
  err_bytes=$(wc -c <"$work/err")
  row "reader closes early (SIGPIPE $sigpipe)" "\`conescan-sim --orbits 100000 --max-rows 1000000000 \\| head -c 4096\`" \
    "ended after $took s (a whole run: 6e7 rows, ~2 min), exit $rc, $err_bytes bytes on stderr"
done

# --- Fuzzing and sanitizers -----------------------------------------------------------------
if [ -z "${SKIP_FUZZ:-}" ]; then
  set +e
  scripts/fuzz.sh >"$work/fuzz" 2>&1
  rc=$?
  set -e
  while read -r target seconds execs corpus outcome; do
    [ "$target" = target ] && continue
    case $target in core | head_spec | options | scene_file) ;; *) continue ;; esac
    row "fuzzing: $target" "\`FUZZ_SECONDS=$seconds scripts/fuzz.sh $target\`" \
      "$seconds s, $execs executions, corpus $corpus inputs: $outcome"
  done <"$work/fuzz"
  [ $rc -eq 0 ] || cat "$work/fuzz" >&2
fi
if [ -z "${SKIP_SANITIZERS:-}" ]; then
  start=$(date +%s)
  set +e
  scripts/test-sanitizers.sh >"$work/asan" 2>&1
  rc=$?
  set -e
  summary=$(grep -E 'tests passed|tests failed' "$work/asan" | tail -n 1)
  row "test suite under ASan + UBSan" "\`scripts/test-sanitizers.sh\`" \
    "exit $rc after $(($(date +%s) - start)) s (build and tests): $summary"
fi

# --- A long run: constant memory, and a last row that is right --------------------------------
step=1
duration=$((rows - 1))
/usr/bin/time -v -o "$work/time-short" "$sim" --step-s 1 --duration-s 9999 >/dev/null
short_rss=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$work/time-short")
start=$(date +%s)
/usr/bin/time -v -o "$work/time-long" "$sim" --step-s $step --duration-s $duration \
  --max-rows $((rows + 1)) | tee >(wc -l >"$work/lines") | tail -n 1 >"$work/last.csv"
for _ in 1 2 3 4 5 6 7 8 9 10; do [ -s "$work/lines" ] && break; sleep 1; done  # wc's last line
took=$(($(date +%s) - start))
long_rss=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$work/time-long")
long_status=$(sed -n 's/.*Exit status: //p' "$work/time-long")
"$sim" --duration-s 0 >"$work/header.csv"
head -n 1 "$work/header.csv" >"$work/last-with-header.csv"
cat "$work/last.csv" >>"$work/last-with-header.csv"
# The same instant from a one-row run: the epoch moved into the mean anomaly at t = 0.
m0_deg=$(/usr/bin/python3 -c "
import math
gm, a = 3.986004418e14, 7280e3  # WGS84 GM (GeographicLib), the paper's a
n = math.sqrt(gm / (a * a * a))
print(repr(math.degrees(math.remainder(n * $duration * $step, 2 * math.pi))))")
"$sim" --duration-s 0 --m0-deg "$m0_deg" >"$work/epoch.csv"
set +e
/usr/bin/python3 - "$work/last-with-header.csv" "$work/epoch.csv" $((duration * step)) >"$work/check" <<'PY'
# The last row of the long run against (1) an independent computation of the paper's scene at
# that time, written from MODEL §3-§6 without the project's code (closed forms of the bias model
# on a sphere, zero attitude, alpha = 0: eta = 90 deg, psi = gamma + sigma), and (2) the one-row
# run whose mean anomaly at t = 0 is the long run's at its last row.
import csv, math, sys
last = next(csv.DictReader(open(sys.argv[1])))
epoch = next(csv.DictReader(open(sys.argv[2])))
t = float(sys.argv[3])
gm, a, e, inc = 3.986004418e14, 7280e3, 0.1, math.radians(97.7)
R, f = 6378137.0, 1 / 298.257223563
gamma, sigma = math.radians(45), math.radians(0.02)
n = math.sqrt(gm / (a * a * a))
m = math.remainder(n * t, 2 * math.pi)
E = m if e < 0.8 else math.pi
for _ in range(50):
    E -= (E - e * math.sin(E) - m) / (1 - e * math.cos(E))
nu = 2 * math.atan2(math.sqrt(1 + e) * math.sin(E / 2), math.sqrt(1 - e) * math.cos(E / 2))
x, y = a * (math.cos(E) - e), a * math.sqrt(1 - e * e) * math.sin(E)
X, Y, Z = x, y * math.cos(inc), y * math.sin(inc)
r = math.sqrt(X * X + Y * Y + Z * Z)
p, e2 = math.hypot(X, Y), f * (2 - f)
lat = math.atan2(Z, p * (1 - e2))
for _ in range(20):
    N = R / math.sqrt(1 - e2 * math.sin(lat) ** 2)
    alt = p * math.cos(lat) + Z * math.sin(lat) - R * math.sqrt(1 - e2 * math.sin(lat) ** 2)
    lat = math.atan2(Z, p * (1 - e2 * N / (N + alt)))
rho = math.asin(R / r)
psi = gamma + sigma
half = math.acos(math.cos(rho) / math.sin(psi))  # Eq. (3) with eta = 90 deg
k = math.sin(gamma) * math.cos(half)
delta, spread = math.atan2(k, math.cos(gamma)), math.acos(math.cos(rho) / math.hypot(math.cos(gamma), k))
eta_s = min((delta + spread, delta - spread), key=lambda v: abs(v - math.pi / 2))
eta_err = math.degrees(eta_s - math.pi / 2)
expected = {
    "t_s": t, "nu_deg": math.degrees(nu) % 360, "r_km": r / 1000, "alt_km": alt / 1000,
    "lat_deg": math.degrees(lat), "rho_deg": math.degrees(rho), "h1_chord_deg": math.degrees(2 * half),
    "h1_phase_deg": 0.0, "h1_eta_err_deg": eta_err, "h1_roll_err_deg": -eta_err,
    "h1_pitch_err_deg": 0.0, "roll_err_deg": -eta_err, "pitch_err_deg": 0.0,
}
def diff(col, got, want):
    d = abs(float(got) - want)
    if col == "nu_deg": d = min(d, 360 - d)
    return d
# At t = 1e8 s the mean anomaly n t is ~1e5 rad, known to ulp(n t) = 1.5e-11 rad in double, so
# the row itself is no better than that: km columns within a e ulp / (1 - e) per ulp, angles
# within (1 + e)^2 / (1 - e^2)^1.5 ulp. The bound: 16 ulp(n t) times a (km) or 70 deg/rad.
ulp_m = math.ulp(n * t)
bound = {"km": 16 * ulp_m * a / 1000, "deg": 16 * ulp_m * 70}
def unit(col): return "km" if col.endswith("_km") else "deg"
worst = {"km": 0.0, "deg": 0.0}
worst_epoch = {"km": 0.0, "deg": 0.0}
for c, v in expected.items():
    if c == "t_s": continue
    worst[unit(c)] = max(worst[unit(c)], diff(c, last[c], v))
    worst_epoch[unit(c)] = max(worst_epoch[unit(c)], diff(c, last[c], float(epoch[c])))
t_ok = float(last["t_s"]) == t
statuses_ok = all(last[c] == "ok" for c in ("h1_status", "status"))
ok = t_ok and statuses_ok and all(worst[u] <= bound[u] and worst_epoch[u] <= bound[u] for u in bound)
print(f"last row t_s = {last['t_s']}, statuses {'ok' if statuses_ok else 'NOT ok'}; it differs from "
      f"an independent computation by at most {worst['km']:.1e} km and {worst['deg']:.1e} deg, "
      f"from a one-row run at --m0-deg {math.degrees(m):.6f} by at most {worst_epoch['km']:.1e} km "
      f"and {worst_epoch['deg']:.1e} deg (bounds from ulp(n t) = {ulp_m:.1e} rad: "
      f"{bound['km']:.1e} km, {bound['deg']:.1e} deg)")
sys.exit(0 if ok else 1)
PY
check_rc=$?
set -e
lines=$(cat "$work/lines")
row "long run: $rows rows" "\`conescan-sim --step-s $step --duration-s $duration --max-rows $((rows + 1))\`" \
  "exit $long_status in $took s, $((lines - 1)) rows; peak RSS $long_rss KiB (10^4 rows: $short_rss KiB); $(cat "$work/check")$([ $check_rc -eq 0 ] || echo ' **MISMATCH**')"
echo "table written to $table" >&2
