#!/usr/bin/env bash
# Sets up, builds and runs the whole test suite with ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
count=$(ctest --test-dir build -N | sed -n 's/^Total Tests: //p')
echo "test: running the $count tests with ctest on $(nproc) cores (about 15 minutes on 2 idle cores)" >&2
start=$SECONDS
ctest --test-dir build --output-on-failure -j"$(nproc)"
echo "test: done in $((SECONDS - start)) s" >&2
