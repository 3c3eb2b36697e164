#!/usr/bin/env bash
# README command 2 (and CI): install what is missing, build with tests, run the whole suite.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
# the benchmark programs are run by hand (tests/bench/*.sh), never by ctest: not built here, to keep CI short
scripts/build.sh -DROLLSIM_BUILD_TESTS=ON -DROLLSIM_BUILD_BENCH=OFF
cd "${ROLLSIM_BUILD_DIR:-build}"
ctest --output-on-failure -j"$(nproc)" --timeout 900
