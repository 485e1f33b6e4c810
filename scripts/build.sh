#!/usr/bin/env bash
# Configures and builds conescan (Release) into build/. Arguments are passed to cmake --build.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" "$@" >/dev/null
