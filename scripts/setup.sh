#!/usr/bin/env bash
# Installs the Debian packages conescan needs, only those that are missing; one line when all are
# present. Idempotent. Extra package names may be given as arguments (e.g. gnuplot-nox). apt's own
# output goes to build/setup.log (shown when it fails).
set -euo pipefail
# One package a line: the build, the core's tests, the orbit and scene layers, Python (matplotlib:
# examples/python), the SGP4 tests' verification data and oracle (python3-sgp4), the frames'
# oracle (python3-erfa), the calibration (Ceres), GNU parallel (the sharded campaign's test), the
# formats' libraries (JSON, XML, TOML).
packages=(
  cmake g++ make
  libglm-dev catch2 libboost-dev
  libgeographiclib-dev libcli11-dev
  liberfa-dev
  nlohmann-json3-dev libpugixml-dev libtomlplusplus-dev
  pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib
  python3-sgp4 python3-erfa
  libceres-dev
  parallel
  gcc-arm-none-eabi libnewlib-arm-none-eabi libstdc++-arm-none-eabi-newlib qemu-system-arm  # the core on a Cortex-M7 under QEMU (tests/flight)
  slurmctld slurmd slurm-client munge  # the one-node Slurm of ctest campaign.slurm (scripts/slurm/)
  chromium python3-html5lib  # the study report's tests: a browser's screenshot, an HTML5 parser
  "$@"
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: the ${#packages[@]} Debian packages conescan needs are installed" >&2
  exit 0
fi
cd "$(dirname "$0")/.."
mkdir -p build
log=build/setup.log
echo "setup: installing ${#missing[@]} Debian packages (${missing[*]}): about 1 to 5 minutes" \
  "on a fresh machine (log: $log)" >&2
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
start=$SECONDS
run() {
  if ! "$@" >>"$log" 2>&1; then
    tail -n 30 "$log" >&2
    echo "setup: '$*' failed (whole log: $log)" >&2
    exit 1
  fi
}
echo "setup: apt-get update" >&2
run $sudo apt-get update -qq
echo "setup: apt-get install" >&2
run $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "setup: installed in $((SECONDS - start)) s" >&2
