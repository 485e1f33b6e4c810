#!/usr/bin/env bash
# Installs the Debian packages conescan needs, only those that are missing; silent when all are
# present. Idempotent. Extra package names may be given as arguments (e.g. gnuplot-nox).
set -euo pipefail
# One package a line: the build, the core's tests, the orbit and scene layers, Python (matplotlib:
# examples/python), the SGP4 tests' verification data and oracle (python3-sgp4), the calibration
# (Ceres), GNU parallel (the sharded campaign's test, issue 17), the formats' libraries (JSON, XML,
# TOML).
packages=(
  cmake g++ make
  libglm-dev catch2 libboost-dev
  libgeographiclib-dev libcli11-dev
  liberfa-dev
  nlohmann-json3-dev libpugixml-dev libtomlplusplus-dev
  pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib
  python3-sgp4
  libceres-dev
  parallel
  "$@"
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "setup: installing ${missing[*]}" >&2
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq >&2
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
