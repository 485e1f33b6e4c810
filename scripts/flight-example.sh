#!/usr/bin/env bash
# Builds examples/flight_software for the Cortex-M7 (tests/flight, cmake/arm-none-eabi-cortex-m7
# .cmake) with a calibration header of your own (scripts/fit-header.py's output) and runs it under
# QEMU's mps2-an500 board. The tools come from scripts/setup.sh.
#   scripts/flight-example.sh CALIBRATION.h [BUILD_DIR]   (default build/flight-example)
set -euo pipefail
if [ $# -lt 1 ] || [ ! -f "$1" ]; then
  echo "usage: scripts/flight-example.sh CALIBRATION.h [BUILD_DIR] (the header: scripts/fit-header.py FIT.json)" >&2
  exit 2
fi
header=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
root=$(cd "$(dirname "$(readlink -f "$0")")/.." && pwd)
build=${2:-$root/build/flight-example}
# calibration.h is what the example includes: the header is copied under that name.
mkdir -p "$build/calibration"
cp "$header" "$build/calibration/calibration.h"
glm=$(dirname "$(find /usr/include /usr/local/include -maxdepth 2 -name vec3.hpp -path '*glm*' | head -1)")
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
log=$build/build.log
if ! { cmake -S "$root/tests/flight" -B "$build" \
         -DCMAKE_TOOLCHAIN_FILE="$root/cmake/arm-none-eabi-cortex-m7.cmake" \
         -DGLM_INCLUDE_DIR="$(dirname "$glm")" -DFLIGHT_CALIBRATION_DIR="$build/calibration" \
         "${launcher[@]}" &&
       cmake --build "$build" --target flight_example.elf; } >"$log" 2>&1; then
  tail -n 30 "$log" >&2
  echo "flight-example: the build failed (log: $log)" >&2
  exit 1
fi
exec qemu-system-arm -M mps2-an500 -display none -monitor none -serial none \
  -chardev stdio,id=out -semihosting-config enable=on,target=native,chardev=out \
  -icount shift=0 -kernel "$build/flight_example.elf"
