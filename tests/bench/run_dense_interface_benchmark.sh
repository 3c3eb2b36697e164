#!/usr/bin/env bash
# The dense interface solver on the 3D pass -> docs/BENCHMARKS-ROLLING.md ("The interface formed and factored").
# samples/rolling-3d-24x12x8.json over its first TRAVEL mm (1 mm steps, cg_tolerance 1e-10) as `direct` + `always`
# (the paper's direct), Mixed II with the paper's interface CG (`krylov`) and Mixed II with `interface_solver: dense`;
# farm-bench times dense against each of the other two (A and B in turn, REPEAT pairs, one thread, CPU = user +
# system, medians and the pairs' ratios), then the runs' Newton iterations, factorizations, interface work, roll
# force and torque from their summary.json.
# Usage: tests/bench/run_dense_interface_benchmark.sh [--rollsim BIN] [--repeat N] [--travel MM] [--threads N]
# This script builds nothing (copy the binary elsewhere if you rebuild meanwhile). It fails only if a run fails.
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
ROLLSIM=$ROOT/build/app/rollsim
REPEAT=3
TRAVEL=4
THREADS=1
while (($#)); do
  case $1 in
    --rollsim) ROLLSIM=$2; shift 2 ;;
    --repeat) REPEAT=$2; shift 2 ;;
    --travel) TRAVEL=$2; shift 2 ;;
    --threads) THREADS=$2; shift 2 ;;
    -h|--help) sed -n 2,9p "$0"; exit 0 ;;
    *) echo "run_dense_interface_benchmark: unknown argument $1" >&2; exit 2 ;;
  esac
done
ROLLSIM=$(realpath "$ROLLSIM")
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
export OMP_NUM_THREADS=$THREADS OPENBLAS_NUM_THREADS=$THREADS

# variant NAME MODE UPDATE INTERFACE -> $WORK/NAME.json
variant() {
  python3 - "$ROOT/samples/rolling-3d-24x12x8.json" "$WORK/$1.json" "$@" "$TRAVEL" <<'PY'
import json, sys
src, dst, name, mode, update, interface, travel = sys.argv[1:]
p = json.load(open(src))
p["name"] = name
p["process"].update(travel=float(travel), travel_increment=1.0)
p["process"].pop("slab_partition", None)
p["solver"].update(mode=mode, update=update, interface_solver=interface, cg_tolerance=1e-10)
json.dump(p, open(dst, "w"))
PY
}
variant direct direct always krylov
variant krylov mixed selective krylov
variant dense mixed selective dense

run() { echo "$ROLLSIM run $WORK/$1.json --out $WORK/out-$1 --threads $THREADS"; }
for base in direct krylov; do
  echo "## dense (A) against $base (B)"
  farm-bench -n "$REPEAT" --warmup 0 --timeout 3600 --vs "$(run "$base")" -- $(run dense) |
    grep -E "farm-bench|cpu s|wall s|peak MiB|A/B cpu|A/B wall"
done

echo "## counts (the last run of each)"
python3 - "$WORK" <<'PY'
import json, sys
print("| variant | Newton iterations | factorizations | CG iterations | columns of K⁺ | roll force [N] | roll torque [N mm] |")
print("|---|---|---|---|---|---|---|")
for v in ("direct", "krylov", "dense"):
    s = json.load(open(f"{sys.argv[1]}/out-{v}/summary.json"))
    so, r = s["solver"], s["results"]["rolling"]
    f = ", ".join(f"{g} {n}" for g, n in so["factorizations"].items())
    print(f"| {v} | {so['newton_iterations']} | {f} | {so['cg_iterations_total']} | {so.get('interface_columns', '–')} "
          f"| {r['roll_force']:.3f} | {r['roll_torque']:.1f} |")
PY
