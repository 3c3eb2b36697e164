#!/usr/bin/env bash
# Newton benchmark of issue 12 -> the tables of docs/BENCHMARKS-NONLINEAR.md: the paper's Example 2 (sample
# cylinder-plastic-2d) in every solver mode and update policy — steps, cut-backs, Newton iterations, factorizations
# and tangent evaluations per group, interface CG iterations, contact force, in-process time, peak memory — and then
# the time ratios against `direct` + `always`, paired, from tests/bench/paired_timing.py.
#
# Usage: tests/bench/run_nonlinear_benchmarks.sh [--rollsim BIN] [--repeat N] [--sample FILE]
# (--sample samples/cylinder-plastic-3d.json: Example 2 in 3D, Table V)
# This script builds nothing. Timing is not a test: it fails only if a run fails.
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
ROLLSIM=$ROOT/build/app/rollsim
REPEAT=5
SAMPLE=$ROOT/samples/cylinder-plastic-2d.json
while (($#)); do
  case $1 in
    --rollsim) ROLLSIM=$2; shift 2 ;;
    --repeat) REPEAT=$2; shift 2 ;;
    --sample) SAMPLE=$(realpath "$2"); shift 2 ;;
    -h|--help) sed -n 2,8p "$0"; exit 0 ;;
    *) echo "run_nonlinear_benchmarks: unknown argument $1" >&2; exit 2 ;;
  esac
done
ROLLSIM=$(realpath "$ROLLSIM")
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
VARIANTS=("skyline always" "direct always" "mixed always" "direct selective" "mixed selective")

echo "| mode | update | steps | cut-backs | Newton iterations | factorizations base / cylinder | tangents base / cylinder | CG iterations | contact force | in-process s | peak MiB |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
for v in "${VARIANTS[@]}"; do
  read -r mode update <<<"$v"
  out=$WORK/$mode-$update
  /usr/bin/time -f "%M" -o "$out.mem" "$ROLLSIM" run "$SAMPLE" --quiet --out "$out" --solver "$mode" --update "$update" >/dev/null
  python3 - "$out" "$mode" "$update" <<'PY'
import json, sys
out, mode, update = sys.argv[1:]
d = json.load(open(out + "/summary.json"))
inc = d["increments"]
f, t = d["solver"]["factorizations"], d["solver"]["stiffness_evaluations"]
peak = int(open(out + ".mem").read().split()[-1]) / 1024
print(f"| {mode} | {update} | {len(inc)} | {sum(i['cutbacks'] for i in inc)} | {d['solver']['newton_iterations']} | "
      f"{f['base']} / {f['cylinder']} | {t['base']} / {t['cylinder']} | {d['solver']['cg_iterations_total']} | "
      f"{d['results']['contact']['cylinder-base']['normal_force']:.2f} | {d['timing']['total_s']:.2f} | {peak:.1f} |")
PY
done

echo
for v in "${VARIANTS[@]}"; do
  read -r mode update <<<"$v"
  [[ $mode == direct && $update == always ]] && continue
  echo "### $mode + $update vs direct + always"
  python3 "$ROOT/tests/bench/paired_timing.py" -n "$REPEAT" \
    --vs "$ROLLSIM run $SAMPLE --quiet --out $WORK/b --solver direct --update always" \
    -- "$ROLLSIM" run "$SAMPLE" --quiet --out "$WORK/a" --solver "$mode" --update "$update" | grep -E "A/B|wall|peak"
done
