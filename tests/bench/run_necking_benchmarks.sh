#!/usr/bin/env bash
# Simo's necking bar (issue 12) -> docs/VALIDATION.md "Simo's necking bar" and docs/images/necking_*.png: the sample
# samples/necking-bar-3d.json on three meshes with F-bar (formulation bbar) and the middle mesh with full
# integration, each end pulled 3.5 mm (--end U: U mm in 10 U steps; the published curves go to 7); load and neck radius per increment (docs/data/necking.csv), the plots, and the
# markdown table beside the reference points (docs/data/necking_reference.csv), with wall time and peak memory.
#
# Usage: tests/bench/run_necking_benchmarks.sh [--rollsim BIN] [--curve BIN] [--out DIR] [--end U] [--only LABELS]
# This script builds nothing (needs the GUI build for rollsim_necking_curve). It fails only if a run fails other
# than by diverging (exit 4: its converged increments are drawn, the table names the status).
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
ROLLSIM=$ROOT/build/app/rollsim
CURVE=$ROOT/build/tests/bench/rollsim_necking_curve
OUT=$ROOT/docs
END=3.5
ONLY=""
while (($#)); do
  case $1 in
    --rollsim) ROLLSIM=$2; shift 2 ;;
    --curve) CURVE=$2; shift 2 ;;
    --out) OUT=$2; shift 2 ;;
    --end) END=$2; shift 2 ;;
    --only) ONLY=$2; shift 2 ;;  # comma-separated labels, e.g. coarse,medium
    -h|--help) sed -n 2,8p "$0"; exit 0 ;;
    *) echo "run_necking_benchmarks: unknown argument $1" >&2; exit 2 ;;
  esac
done
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
SAMPLE=$ROOT/samples/necking-bar-3d.json

# label  n_core n_ring n_axial grading formulation
VARIANTS=("coarse 2 2 10 1.15 bbar" "medium 3 3 16 1.1 bbar" "fine 4 4 24 1.07 bbar" "medium-full 3 3 16 1.1 full")
ARGS=()
echo "| mesh | elements | dofs | steps | cut-backs | Newton iterations | wall s | peak MiB |"
echo "|---|---|---|---|---|---|---|---|"
for v in "${VARIANTS[@]}"; do
  read -r label core ring axial grading formulation <<<"$v"
  [[ -z $ONLY || ,$ONLY, == *,$label,* ]] || continue
  python3 - "$SAMPLE" "$WORK/$label.json" "$core" "$ring" "$axial" "$grading" "$formulation" "$END" <<'PY'
import json, sys
src, dst, core, ring, axial, grading, formulation, end = sys.argv[1:]
p = json.load(open(src))
for bc in p["boundary_conditions"]:
    if "uz" in bc:
        bc["uz"] = float(end)
p["analysis"]["increments"] = round(10 * float(end))
b = p["bodies"][0]
b["formulation"] = formulation
b["mesh"].update({"n_core": int(core), "n_ring": int(ring), "n_axial": int(axial), "axial_grading": float(grading)})
p["output"] = {"vtu": False}
json.dump(p, open(dst, "w"))
PY
  start=$(date +%s.%N)
  # a diverged run (exit 4) still has its converged increments in summary.json: the table says which
  /usr/bin/time -f "%M" -o "$WORK/$label.mem" "$ROLLSIM" run "$WORK/$label.json" --quiet --out "$WORK/$label" \
    >/dev/null 2>"$WORK/$label.err" || [ $? -eq 4 ] || { cat "$WORK/$label.err" >&2; exit 1; }
  end=$(date +%s.%N)
  python3 - "$WORK/$label" "$label" "$start" "$end" "$(tail -1 "$WORK/$label.mem")" <<'PY'
import json, sys
out, label, start, end, mem = sys.argv[1:]
d = json.load(open(out + "/summary.json"))
inc = d["increments"]
print(f"| {label} ({d['status']}) | {d['model']['elements']} | {d['model']['dofs']} | {len(inc)} | {sum(i['cutbacks'] for i in inc)} | "
      f"{sum(i['newton_iterations'] for i in inc)} | {float(end) - float(start):.1f} | {int(mem) / 1024:.0f} |")
PY
  ARGS+=("$label=$WORK/$label/summary.json")
done
echo
mkdir -p "$OUT/data" "$OUT/images"
"$CURVE" --out "$WORK/curves" --reference "$ROOT/docs/data/necking_reference.csv" "${ARGS[@]}"
cp "$WORK/curves/necking.csv" "$OUT/data/necking.csv"
cp "$WORK/curves/necking_load.png" "$WORK/curves/necking_radius.png" "$OUT/images/"
