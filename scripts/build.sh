#!/usr/bin/env bash
# Configures and builds conescan (Release) into build/, saying what it does as it goes: each
# target as it is built, with the share done and the time so far (on a terminal and in a log
# alike; the compiler's own output goes to build/build.log). Arguments are passed to
# cmake --build (e.g. --target conescan-sim).
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p build
log=build/build.log
: >"$log"
launcher=()
# ccache, where the machine has it, makes a rebuild of unchanged sources take seconds.
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
echo "build: configuring (cmake, Release, into build/)" >&2
if ! cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" >>"$log" 2>&1; then
  tail -n 40 "$log" >&2
  echo "build: cmake failed (whole log: $log)" >&2
  exit 1
fi
echo "build: compiling with $(nproc) jobs: a first build takes 3 to 10 minutes on 2 cores, a" \
  "rebuild seconds (log: $log)" >&2
start=$SECONDS
set +e
cmake --build build -j"$(nproc)" "$@" 2>&1 | tee -a "$log" |
  while IFS= read -r line; do
    # make's "[ 45%] Building CXX object <dir>/CMakeFiles/<target>.dir/<file>.o" and
    # "[ 45%] Built target <target>": the share done, the file or target, the time so far.
    s=$((SECONDS - start))
    if [[ $line =~ ^\[\ *([0-9]+)%\]\ Building\ CXX\ object\ .*\.dir/(.*)\.o$ ]]; then
      printf 'build: %3d%% compiling %s (%d:%02d)\n' "${BASH_REMATCH[1]}" "${BASH_REMATCH[2]}" \
        $((s / 60)) $((s % 60)) >&2
    elif [[ $line =~ ^\[\ *([0-9]+)%\]\ Built\ target\ (.*)$ ]]; then
      targets=$((${targets:-0} + 1))
      printf 'build: %3d%% built target %d, %s (%d:%02d)\n' "${BASH_REMATCH[1]}" "$targets" \
        "${BASH_REMATCH[2]}" $((s / 60)) $((s % 60)) >&2
    fi
  done
status=${PIPESTATUS[0]}
set -e
if [ "$status" -ne 0 ]; then
  grep -E -m 20 "error|Error" "$log" >&2 || tail -n 40 "$log" >&2
  echo "build: the build failed (whole log: $log)" >&2
  exit "$status"
fi
echo "build: done in $((SECONDS - start)) s" >&2
