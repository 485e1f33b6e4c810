#!/usr/bin/env bash
# A year's calendar of Sun and Moon blinding (MODEL §13, docs/SUN_MOON.md "Sun and Moon") for the
# example orbits: 800 km circular, sun-synchronous (J2 node drift), ascending node at 09:00 and at
# 10:30 mean local time, two pitch-axis heads (alpha = 0, beta = +90 and -90, gamma = 45 deg, no
# misalignment, a pencil beam: fov = 0) on an orbit-pointing satellite, over YEAR (default 2026).
# About 10 s on a two-core machine (the old row-by-row version of this script took 155 s).
#
# First, the rule's table: for nodes from 06:00 to 12:00 every half hour, the year's range of the
# Sun's angle beta above the orbit plane (from the +y head's hK_sun_deg = 90 + beta - gamma, seven
# rows a day) and the cone angles gamma a pitch-axis head must avoid: gamma within
# fov/2 + r_Sun of 90 + beta (the +y head, spin axis on the negative orbit normal) or 90 - beta
# (the -y head), clipped to [0, 90]. Then, for each of the two orbits, conescan-sim --calendar
# (src/simulation/blinding_calendar.hpp): every interval in which the Sun or the Moon takes a head's
# crossings and every interval with a body on a head's cone, found from the geometry at a
# resolution of 1 s, edges to 1 ms.
# The node's right ascension at an epoch: RAAN = GMST + 15 deg/h (LTAN - UT) (the mean Sun's
# right ascension, GMST - 15 deg/h (UT - 12 h), plus the node's hour angle from it); GMST from
# IAU 2006 (ERA and its polynomial), UT1 = UTC, TT = UTC + 69.184 s (TAI - UTC = 37 s); the
# equation of the equinoxes (< 0.005 deg) is left out. A sun-synchronous node keeps its angle to
# the mean Sun, so LTAN is a mean local time, the same on every day; the true local time swings
# with the equation of time (+-16 min).
#
# Writes docs/data/blinding-beta.csv (the rule's table), docs/data/blinding-days.csv (per orbit,
# head, body and day: seconds on the cone, seconds lost, events: the calendar's days.csv),
# docs/data/blinding-year.csv (per orbit, head and body: the calendar's seasons.csv) and
# docs/blinding-calendar.png (scripts/calendar-picture.py: day of the year against the argument
# of latitude, per orbit and head); each orbit's calendar in $BUILD_DIR/blinding/0900 and 1030.
# BUILD_DIR (default build): the build directory; YEAR: the year; FOV_DEG: the heads' field (the
# head key fov=, MODEL §12; default 0).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
year=${YEAR:-2026}
fov=${FOV_DEG:-0}

scripts/setup.sh
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
echo "blinding-calendar: building conescan-sim (minutes when nothing is built yet)" >&2
cmake --build "$build" -j"$(nproc)" --target conescan-sim >/dev/null

# raan_deg DAY LTAN_HOURS: the RAAN at 00:00 UTC of day DAY (1-based) of YEAR.
raan_deg() {
  /usr/bin/python3 - "$year" "$1" "$2" <<'EOF'
import datetime, math, sys
year, day, ltan = int(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3])
date = datetime.date(year, 1, 1) + datetime.timedelta(days=day - 1)
jd_ut = date.toordinal() + 1721424.5  # the Julian Date of its 00:00
t = (jd_ut + 69.184 / 86400 - 2451545.0) / 36525
era = 2 * math.pi * ((0.7790572732640 + 1.00273781191135448 * (jd_ut - 2451545.0)) % 1.0)
gmst = math.degrees(era) + (0.014506 + 4612.156534 * t + 1.3915817 * t * t
                            - 0.00000044 * t ** 3 - 0.000029956 * t ** 4) / 3600
print(date.isoformat(), repr((gmst + 15 * ltan) % 360))
EOF
}

heads=(--head beta=90,sigma=0 --head beta=-90,sigma=0)
[ "$fov" != 0 ] && heads=(--head "beta=90,sigma=0,fov=$fov" --head "beta=-90,sigma=0,fov=$fov")
days=$(/usr/bin/python3 -c "import calendar; print(366 if calendar.isleap($year) else 365)")
scene=(--model scan --earth wgs84 --intrusions --a-km 7178.137 --e 0 --sun-sync --j2 "${heads[@]}")

mkdir -p "$build/blinding" docs/data
beta_csv=docs/data/blinding-beta.csv
echo "node,beta_min_deg,beta_max_deg,plus_y_avoid_gamma_from,plus_y_avoid_gamma_to,minus_y_avoid_gamma_from,minus_y_avoid_gamma_to" \
  >"$beta_csv"
echo "blinding-calendar: the Sun's beta over $year for nodes 06:00 to 12:00" >&2
for half_hours in $(seq 12 24); do
  ltan=$(awk -v h="$half_hours" 'BEGIN { print h / 2 }')
  read -r epoch raan < <(raan_deg 1 "$ltan")
  node=$(awk -v h="$half_hours" 'BEGIN { printf "%02d:%02d", int(h / 2), (h % 2) * 30 }')
  "$build"/conescan-sim "${scene[@]}" --epoch "${epoch}T00:00:00" --raan-deg "$raan" \
    --step-s 12342.857142857143 --duration-s $((days * 86400 - 1)) |
    awk -F, -v node="$node" -v fov="$fov" '
      NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
      {
        beta = $col["h1_sun_deg"] + 45 - 90
        if (NR == 2 || beta < low) low = beta
        if (NR == 2 || beta > high) high = beta
      }
      END {
        e = fov / 2 + 0.2713  # r_Sun at perihelion
        plus_from = 90 + low - e; plus_to = 90 + high + e
        if (plus_from < 0) plus_from = 0
        minus_from = 90 - high - e; minus_to = 90 - low + e
        if (minus_from < 0) minus_from = 0
        printf "%s,%.2f,%.2f,%s,%s,%s,%s\n", node, low, high,
          plus_from < 90 ? sprintf("%.2f", plus_from) : "-", plus_from < 90 ? sprintf("%.2f", plus_to < 90 ? plus_to : 90) : "-",
          minus_from < 90 ? sprintf("%.2f", minus_from) : "-", minus_from < 90 ? sprintf("%.2f", minus_to < 90 ? minus_to : 90) : "-"
      }' >>"$beta_csv"
done
days_csv=docs/data/blinding-days.csv
year_csv=docs/data/blinding-year.csv
echo "orbit,head,body,day,date,on_cone_s,lost_s,lost_events" >"$days_csv"
echo "orbit,raan_deg,head,body,on_cone_days,first_on_cone_day,last_on_cone_day,lost_days,first_lost_day,last_lost_day,lost_events,lost_s,lost_hours,shortest_event_s,longest_event_s" >"$year_csv"
pictures=()
for node in 09:00 10:30; do
  ltan=$(/usr/bin/python3 -c "h, m = '$node'.split(':'); print(int(h) + int(m) / 60)")
  read -r epoch raan < <(raan_deg 1 "$ltan")
  dir="$build/blinding/${node/:/}"
  echo "blinding-calendar: $node node (RAAN $raan deg on $epoch): the year's calendar" >&2
  "$build"/conescan-sim "${scene[@]}" --epoch "${epoch}T00:00:00" --raan-deg "$raan" \
    --duration-s $((days * 86400)) --calendar "$dir"
  tail -n +2 "$dir/days.csv" | sed "s/^/$node,/" >>"$days_csv"
  tail -n +2 "$dir/seasons.csv" | sed "s/^/$node,$raan,/" >>"$year_csv"
  pictures+=("$dir=node at $node mean local time")
done

/usr/bin/python3 scripts/calendar-picture.py docs/blinding-calendar.png "${pictures[@]}" \
  --title "Sun and Moon in the scan, $year: 800 km sun-synchronous orbit, pitch-axis heads (+y: h1, -y: h2), gamma = 45 deg, $([ "$fov" = 0 ] && echo "pencil beam" || echo "field $fov deg")"
column -s, -t "$beta_csv" >&2
column -s, -t "$year_csv" | cut -c1-160 >&2
echo "blinding-calendar: wrote $beta_csv, $days_csv, $year_csv and docs/blinding-calendar.png" \
  "in $SECONDS s" >&2
