#!/usr/bin/env bash
# README command 1: install what is missing, build, and run the main job on the default sample.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh -DROLLSIM_BUILD_TESTS=OFF
SAMPLE=${1:-samples/rolling-2d-36x6.json}
OUT=results/$(basename "$SAMPLE" .json)
build/app/rollsim run "$SAMPLE" --out "$OUT"
echo "rollsim: results of $SAMPLE are in $OUT/ (summary.json; result.vtu and results.pvd open in ParaView)"
