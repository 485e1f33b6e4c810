#!/usr/bin/env bash
# The blinding calendar of any scene, as CSV and as a picture (docs/SUN_MOON.md, "A calendar for
# any orbit"):
#
#   scripts/calendar.sh DIR [conescan-sim scene options...]
#
# runs `conescan-sim OPTIONS --calendar DIR` (a year from the epoch unless --duration-s or
# --orbits says otherwise; events sampled 1 s apart where a body can blind a head unless --step-s
# says otherwise; edges to 1 ms), which writes DIR/lost.csv, on-cone.csv, days.csv and
# seasons.csv, then draws DIR/calendar.png (scripts/calendar-picture.py: one panel per head) and
# prints seasons.csv. The scene is any conescan-sim scene with --model scan: elements, --tle,
# --omm, --oem, an attitude file, any heads and fields, a scene file (--config).
# BUILD_DIR (default build): where conescan-sim is (built here when missing).
set -euo pipefail
if [ $# -lt 1 ] || [[ "$1" == -* ]]; then
  echo "usage: scripts/calendar.sh DIR [conescan-sim scene options...]" >&2
  exit 2
fi
dir=$1
shift
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
if [ ! -x "$build/conescan-sim" ]; then
  "$root/scripts/setup.sh"
  echo "calendar: building conescan-sim (minutes when nothing is built yet)" >&2
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$build" -j"$(nproc)" --target conescan-sim >/dev/null
fi
"$build/conescan-sim" "$@" --calendar "$dir"
/usr/bin/python3 "$root/scripts/calendar-picture.py" "$dir/calendar.png" "$dir"
column -s, -t "$dir/seasons.csv"
