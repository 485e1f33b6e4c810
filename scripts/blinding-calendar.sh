#!/usr/bin/env bash
# A year's calendar of Sun and Moon blinding (MODEL §13, docs/SUN_MOON.md "Sun and Moon") for the
# example orbits: 800 km circular, sun-synchronous (J2 node drift), ascending node at 09:00 and at
# 10:30 mean local time, two pitch-axis heads (alpha = 0, beta = +90 and -90, gamma = 45 deg, no
# misalignment, a pencil beam: fov = 0) on an orbit-pointing satellite, over YEAR (default 2026).
# About a minute on an idle two-core machine (three with other work on it).
#
# First, the rule's table: for nodes from 06:00 to 12:00 every half hour, the year's range of the
# Sun's angle beta above the orbit plane (from the +y head's hK_sun_deg = 90 + beta - gamma, seven
# rows a day) and the cone angles gamma a pitch-axis head must avoid: gamma within
# fov/2 + r_Sun of 90 + beta (the +y head, spin axis on the negative orbit normal) or 90 - beta
# (the -y head). Then, for each of the two orbits, conescan-sim --intrusions runs
#   1. the year at one row a minute (525 600 rows): each head's Sun angle from its cone
#      (hK_sun_deg) and status per row, reduced by awk to the rows where the Sun is on the cone
#      (|hK_sun_deg| <= r_Sun, 0.2666 deg) or a body blinds the head (status sun, moon): the
#      season, and the Moon's events sampled a minute apart;
#   2. each day of the Sun's season (a day whose smallest |hK_sun_deg| is within 0.3 deg) again at
#      one row a second: a crossing is lost for seconds at a time (the Sun at the limb at a
#      crossing), which rows a minute apart only sample;
#   3. the year at one row a second with --summary (31.5 million rows): each head's fraction of
#      the year lost to each body (sun_lost_fraction, moon_lost_fraction), as hours.
# The node's right ascension at an epoch: RAAN = GMST + 15 deg/h (LTAN - UT) (the mean Sun's
# right ascension, GMST - 15 deg/h (UT - 12 h), plus the node's hour angle from it); GMST from
# IAU 2006 (ERA and its polynomial), UT1 = UTC, TT = UTC + 69.184 s (TAI - UTC = 37 s); the
# equation of the equinoxes (< 0.005 deg) is left out. A sun-synchronous node keeps its angle to
# the mean Sun, so LTAN is a mean local time, the same on every day (step 2 starts each day at the
# node with that day's RAAN); the true local time swings with the equation of time (+-16 min).
#
# Writes docs/data/blinding-beta.csv (the rule's table), docs/data/blinding-days.csv (per orbit, head and day: minutes with the Sun on the cone,
# seconds lost to the Sun (season days), minute rows lost to the Moon), docs/data/blinding-year.csv
# (per orbit and head: days on the cone, days with a crossing lost, hours lost to each body) and
# docs/blinding-calendar.png (day of year against minutes since the ascending node, per orbit and
# head: bench/charts/blinding_calendar.gp); the events themselves in $BUILD_DIR/blinding/.
# BUILD_DIR (default build): the build directory; YEAR: the year; FOV_DEG: the heads' field (the
# head key fov=, MODEL §12; default 0).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
year=${YEAR:-2026}
fov=${FOV_DEG:-0}

scripts/setup.sh gnuplot-nox
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

# events FIRST_DAY ON_LINES: conescan-sim's CSV on stdin -> "day,orbit_min,head,what" lines
# (what: sun, moon, and with ON_LINES 1 also on) and, at the end,
# "#day,head,on_rows,min_offset,sun_rows,moon_rows" per day and head. Minutes since the ascending node: the last northward crossing of the equator
# (interpolated), the first row being at the node.
events() {
  awk -F, -v first_day="$1" -v on_lines="$2" '
    NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
    {
      t = $col["t_s"]; lat = $col["lat_deg"]
      if (NR == 2) node_t = t
      else if (last_lat < 0 && lat >= 0) node_t = last_t + (t - last_t) * (-last_lat) / (lat - last_lat)
      last_t = t; last_lat = lat
      day = first_day + int(t / 86400); minute = (t - node_t) / 60
      for (h = 1; h <= 2; ++h) {
        sun = $col["h" h "_sun_deg"]; state = $col["h" h "_status"]
        if (sun < 0) sun = -sun
        if (!((h, day) in low) || sun < low[h, day]) low[h, day] = sun
        if (sun <= 0.2666) { ++on[h, day]; if (on_lines) printf "%d,%.3f,%d,on\n", day, minute, h }
        if (state == "sun") { ++lost[h, day]; printf "%d,%.3f,%d,sun\n", day, minute, h }
        if (state == "moon") { ++moon[h, day]; printf "%d,%.3f,%d,moon\n", day, minute, h }
      }
    }
    END {
      for (key in low) {
        split(key, k, SUBSEP)
        printf "#%d,%d,%d,%.6f,%d,%d\n", k[2], k[1], on[key] + 0, low[key], lost[key] + 0, moon[key] + 0
      }
    }'
}

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
        printf "%s,%.2f,%.2f,%s,%s,%s,%s\n", node, low, high,
          plus_from < 90 ? sprintf("%.2f", plus_from) : "-", plus_from < 90 ? sprintf("%.2f", plus_to < 90 ? plus_to : 90) : "-",
          minus_from < 90 ? sprintf("%.2f", minus_from) : "-", minus_from < 90 ? sprintf("%.2f", minus_to < 90 ? minus_to : 90) : "-"
      }' >>"$beta_csv"
done
days_csv=docs/data/blinding-days.csv
year_csv=docs/data/blinding-year.csv
echo "orbit,head,day,sun_on_cone_min,sun_lost_s,moon_lost_rows" >"$days_csv"
echo "orbit,head,raan_deg,days_sun_on_cone,days_sun_lost,sun_lost_hours,moon_lost_hours" >"$year_csv"

for node in 09:00 10:30; do
  ltan=$(/usr/bin/python3 -c "h, m = '$node'.split(':'); print(int(h) + int(m) / 60)")
  read -r epoch raan < <(raan_deg 1 "$ltan")
  coarse="$build/blinding/minutes-${node/:/}.csv"
  fine="$build/blinding/seconds-${node/:/}.csv"
  echo "blinding-calendar: $node node (RAAN $raan deg on $epoch): the year, a row a minute" >&2
  "$build"/conescan-sim "${scene[@]}" --epoch "${epoch}T00:00:00" --raan-deg "$raan" \
    --step-s 60 --duration-s $((days * 86400 - 60)) | events 1 1 >"$coarse"
  season=$(awk -F, '/^#/ && $4 <= 0.3 { print substr($1, 2) }' "$coarse" | sort -un)
  echo "blinding-calendar: $node node: $(echo "$season" | grep -c . || true) season days, a row a second" >&2
  : >"$fine"
  for day in $season; do
    read -r date raan_day < <(raan_deg "$day" "$ltan")
    "$build"/conescan-sim "${scene[@]}" --epoch "${date}T00:00:00" --raan-deg "$raan_day" \
      --step-s 1 --duration-s 86399 | events "$day" 0 >>"$fine"
  done
  # Per day and head: the season's minutes from the minute rows, the Sun's seconds from the
  # second rows, the Moon's sampled rows from the minute rows.
  awk -F, -v node="$node" -v ndays="$days" '
    FNR == NR { if (/^#/) { d = substr($1, 2); on[d, $2] = $3; moon[d, $2] = $6 } next }
    /^#/ { sun[substr($1, 2), $2] = $5 }
    END {
      for (h = 1; h <= 2; ++h)
        for (d = 1; d <= ndays; ++d)
          printf "%s,h%d,%d,%d,%d,%d\n", node, h, d, on[d, h] + 0, sun[d, h] + 0, moon[d, h] + 0
    }' "$coarse" "$fine" >>"$days_csv"
  echo "blinding-calendar: $node node: the year, a row a second, --summary" >&2
  "$build"/conescan-sim "${scene[@]}" --epoch "${epoch}T00:00:00" --raan-deg "$raan" \
    --step-s 1 --duration-s $((days * 86400 - 1)) --max-rows 40000000 --summary |
    awk -F, -v node="$node" -v raan="$raan" -v days_csv="$days_csv" '
    NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
    $col["source"] ~ /^h/ {
      head = $col["source"]; on_days = 0; lost_days = 0
      while ((getline line <days_csv) > 0) {
        split(line, f, ",")
        if (f[1] == node && f[2] == head) { on_days += f[4] > 0; lost_days += f[5] > 0 }
      }
      close(days_csv)
      printf "%s,%s,%s,%d,%d,%.2f,%.2f\n", node, head, raan, on_days, lost_days,
        $col["sun_lost_fraction"] * $col["rows"] / 3600, $col["moon_lost_fraction"] * $col["rows"] / 3600
    }' >>"$year_csv"
done

gnuplot -e "dir='$build/blinding'; output='docs/blinding-calendar.png'; year='$year'" \
  bench/charts/blinding_calendar.gp 2> >(grep -v "no valid points" >&2)
column -s, -t "$beta_csv" >&2
column -s, -t "$year_csv" >&2
echo "blinding-calendar: wrote $beta_csv, $days_csv, $year_csv and docs/blinding-calendar.png" >&2
