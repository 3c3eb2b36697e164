#!/usr/bin/env bash
# The dense interface solver on the 3D pass -> docs/BENCHMARKS-ROLLING.md ("The interface formed and factored").
# samples/rolling-3d-24x12x8.json over its first TRAVEL mm (1 mm steps, cg_tolerance 1e-10) as `direct` + `always`
# (the paper's direct), Mixed II with the paper's interface CG (`krylov`) and Mixed II with `interface_solver: dense`;
# tests/bench/paired_timing.py times dense against each of the other two (A and B in turn, REPEAT pairs, one thread, CPU = user +
# system, medians and the pairs' ratios), then the runs' Newton iterations, factorizations, interface work, roll
# force and torque from their summary.json.
# --slab NXxNWxNT refines the slab (48x24x8: the issue's mesh 4x finer, the same roll); --skip-krylov times dense
# against direct only (Krylov Mixed II takes minutes on the finer mesh).
# Usage: tests/bench/run_dense_interface_benchmark.sh [--rollsim BIN] [--repeat N] [--travel MM] [--threads N]
#        [--slab NXxNWxNT] [--skip-krylov]
# This script builds nothing (copy the binary elsewhere if you rebuild meanwhile). It fails only if a run fails.
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
ROLLSIM=$ROOT/build/app/rollsim
REPEAT=3
TRAVEL=4
THREADS=1
SLAB=24x12x8
BASES="direct krylov"
while (($#)); do
  case $1 in
    --rollsim) ROLLSIM=$2; shift 2 ;;
    --repeat) REPEAT=$2; shift 2 ;;
    --travel) TRAVEL=$2; shift 2 ;;
    --threads) THREADS=$2; shift 2 ;;
    --slab) SLAB=$2; shift 2 ;;
    --skip-krylov) BASES=direct; shift ;;
    -h|--help) sed -n 2,12p "$0"; exit 0 ;;
    *) echo "run_dense_interface_benchmark: unknown argument $1" >&2; exit 2 ;;
  esac
done
ROLLSIM=$(realpath "$ROLLSIM")
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
export OMP_NUM_THREADS=$THREADS OPENBLAS_NUM_THREADS=$THREADS

# variant NAME MODE UPDATE INTERFACE -> $WORK/NAME.json
variant() {
  python3 - "$ROOT/samples/rolling-3d-24x12x8.json" "$WORK/$1.json" "$@" "$TRAVEL" "$SLAB" <<'PY'
import json, sys
src, dst, name, mode, update, interface, travel, slab = sys.argv[1:]
p = json.load(open(src))
p["name"] = name
nx, nw, nt = (int(v) for v in slab.split("x"))
p["process"].update(travel=float(travel), travel_increment=1.0, slab_nx=nx, slab_nw=nw, slab_nt=nt)
p["process"].pop("slab_partition", None)
p["solver"].update(mode=mode, update=update, interface_solver=interface, cg_tolerance=1e-10)
json.dump(p, open(dst, "w"))
PY
}
variant direct direct always krylov
variant krylov mixed selective krylov
variant dense mixed selective dense
echo "## slab $SLAB, first $TRAVEL mm, $THREADS thread(s)"

run() { echo "$ROLLSIM run $WORK/$1.json --out $WORK/out-$1 --threads $THREADS"; }
for base in $BASES; do
  echo "## dense (A) against $base (B)"
  python3 "$ROOT/tests/bench/paired_timing.py" -n "$REPEAT" --warmup 0 --vs "$(run "$base")" -- $(run dense) |
    grep -E "cpu s|wall s|peak MiB|A/B cpu|A/B wall"
done

echo "## counts (the last run of each)"
python3 - "$WORK" <<'PY'
import json, sys
print("| variant | Newton iterations | factorizations | CG iterations | columns of K⁺ | assembly / factorizations / solves s "
      "| roll force [N] | roll torque [N mm] |")
print("|---|---|---|---|---|---|---|---|")
import os
for v in ("direct", "krylov", "dense"):
    if not os.path.exists(f"{sys.argv[1]}/out-{v}/summary.json"):
        continue
    s = json.load(open(f"{sys.argv[1]}/out-{v}/summary.json"))
    so, r = s["solver"], s["results"]["rolling"]
    f = ", ".join(f"{g} {n}" for g, n in so["factorizations"].items())
    t = s["timing"]
    print(f"| {v} | {so['newton_iterations']} | {f} | {so['cg_iterations_total']} | {so.get('interface_columns', '–')} "
          f"| {t['stiffness_s']:.1f} / {t['factorize_s']:.1f} / {t['solve_s']:.1f} "
          f"| {r['roll_force']:.3f} | {r['roll_torque']:.1f} |")
PY
